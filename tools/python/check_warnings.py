#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks the warnings list of a run's summary.json against the kinds a deck is expected to raise.

  check_warnings.py OUT [--expect KIND ...]

OUT is the run's output folder (or its summary.json). Exit 0 when the set of warning kinds equals
the expected set (none by default), 1 otherwise, printing each warning. The verification decks run
with the default guards (solver/guards/README.md): a guard that cries wolf on a verified run, or
stays silent where a deck is known to trip it, fails the deck's `verify_NAME_warnings` test.
"""
import argparse
import json
import os
import sys

from history_checks import report_failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", help="the run's output folder or its summary.json")
    ap.add_argument("--expect", nargs="*", default=[], metavar="KIND", help="warning kinds the run must raise")
    a = ap.parse_args()
    path = os.path.join(a.out, "summary.json") if os.path.isdir(a.out) else a.out
    try:
        with open(path) as f:
            summary = json.load(f)
    except (OSError, ValueError) as e:
        print(f"{path}: error: {e}", file=sys.stderr)
        return 2
    warnings = summary.get("warnings")
    if warnings is None:
        print(f"{path}: error: no 'warnings' list (a summary.json of an older tribex?)", file=sys.stderr)
        return 2
    for w in warnings:
        print(f"  {w['kind']}: {w['message']}")
    got, want = {w["kind"] for w in warnings}, set(a.expect)
    failures = [f"warning kinds {sorted(got) or 'none'}, expected {sorted(want) or 'none'}"] if got != want else []
    return report_failures(failures, ok=f"OK: warning kinds {sorted(got) or 'none'}, as expected")


if __name__ == "__main__":
    sys.exit(main())
