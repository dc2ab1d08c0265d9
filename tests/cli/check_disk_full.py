#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Issue 29, item 17: a run whose output folder fills up (a 300 KiB tmpfs) must end with exit 3 and
"no space left on device (N bytes free in FOLDER) while writing FILE" (issue 54 item 13), and keep valid what it wrote: summary.json (status
"output failure"), a results.h5 that h5py opens whose XDMF names only steps that are in it, and
history.csv rows that parse (the last one may be cut by the full disk).

  check_disk_full.py OUT STDERR_FILE EXIT_CODE
"""
import csv
import json
import os
import re
import sys

import h5py

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
from history_checks import report_failures  # noqa: E402


def main():
    out, err_file, code = sys.argv[1], sys.argv[2], int(sys.argv[3])
    failures = []
    said = open(err_file).read()
    if code != 3:
        failures.append(f"exit code {code}, expected 3")
    if not re.search(r"no space left on device \(\d+ bytes free in \S+\) while writing \S+", said):
        failures.append(f"stderr does not name the full device and the file: {said!r}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    if summary["exit_code"] != 3 or not summary["status"].startswith("output failure: no space left on device ("):
        failures.append(f"summary.json: exit_code {summary['exit_code']}, status {summary['status'][:80]!r}")
    with h5py.File(os.path.join(out, "results.h5"), "r") as f:
        steps = set(f["steps"])
    named = set(re.findall(r"(step_\d+)", open(os.path.join(out, "results.xdmf")).read()))
    if not named or not named <= steps:
        failures.append(f"results.xdmf names {sorted(named - steps)} not in results.h5 ({len(steps)} steps)")
    rows = list(csv.reader(open(os.path.join(out, "history.csv"))))
    header, body = rows[0], rows[1:-1]  # the last row may be cut by the full disk
    if header[:2] != ["step", "time"] or not body or any(len(r) != len(header) for r in body):
        failures.append("history.csv is not a header and whole rows")
    else:
        [float(v) for r in body for v in r]
    return report_failures(failures, ok=f"OK: exit 3 '{said.strip()[:90]}...'; {len(named)} results steps, {len(body)} history rows kept")

if __name__ == "__main__":
    sys.exit(main())
