#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The run's identity in summary.json and log.txt (issue 22, scope 5): tribex version with git
describe, the deck path and the SHA-256 of its bytes (checked against hashlib), the start time in
ISO 8601 UTC, the host, the rank count and the energy unit. Exit 1 naming every missing piece.

usage: check_identity.py OUTPUT_FOLDER DECK
"""
import hashlib
import json
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
from history_checks import report_failures  # noqa: E402


def main():
    out, deck = sys.argv[1], sys.argv[2]
    s = json.load(open(os.path.join(out, "summary.json")))
    want = hashlib.sha256(open(deck, "rb").read()).hexdigest()
    checks = [
        ("tribex_version", re.match(r"^\d+\.\d+\.\d+ \((git \S+|not built from a git checkout)\)$", s.get("tribex_version", ""))),
        ("deck", s.get("deck") == deck),
        ("deck_sha256", s.get("deck_sha256") == want),
        ("started", re.match(r"^\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ$", s.get("started", ""))),
        ("host", bool(s.get("host"))),
        ("ranks", s.get("ranks") == 1),
        ("energy_unit", s.get("energy_unit") == "J"),
    ]
    failures = [f"summary.json {key} = {s.get(key)!r}" for key, ok in checks if not ok]
    first = open(os.path.join(out, "log.txt")).readline()
    if f"(sha256 {want})" not in first or "| energies in J" not in first or s.get("tribex_version", "?") not in first:
        failures.append(f"log.txt first line lacks the identity: {first.strip()}")
    return report_failures(failures, ok=f"identity OK: {first.strip()}")


if __name__ == "__main__":
    sys.exit(main())
