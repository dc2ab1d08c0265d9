#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks a run stopped or warned by the run guards (solver/guards/README.md) left what the README
promises: the exit code, a valid summary.json whose warnings list holds the expected kinds, a readable
history.csv (header and numeric rows), and log.txt with a `warning:` line per run-time warning and the
closing line.

  check_guard_run.py OUT --exit CODE --kinds KIND ... [--says TEXT] [--source TERM]
"""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
from history_checks import report_failures  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--exit", type=int, required=True, dest="code", help="the exit code in summary.json")
    ap.add_argument("--kinds", nargs="*", required=True, help="warning kinds the list must hold (exactly)")
    ap.add_argument("--says", default="", help="text the closing line of log.txt must contain")
    ap.add_argument("--source", help="the ledger term the energy_error warning must name (e.g. contact_work)")
    a = ap.parse_args()
    failures = []
    with open(os.path.join(a.out, "summary.json")) as f:
        summary = json.load(f)  # raises on invalid JSON
    if summary["exit_code"] != a.code:
        failures.append(f"exit_code {summary['exit_code']}, expected {a.code}")
    kinds = [w["kind"] for w in summary["warnings"]]
    if sorted(set(kinds)) != sorted(set(a.kinds)) or len(kinds) != len(set(kinds)):
        failures.append(f"warning kinds {kinds}, expected each of {sorted(a.kinds)} once")
    for w in summary["warnings"]:
        if not (w["max_value"] >= w["value"] > w["threshold"] or w["kind"] in ("unsafe_choice", "adhesion_cutoff")):
            failures.append(f"{w['kind']}: value {w['value']} / max {w['max_value']} vs threshold {w['threshold']}")
        if w["max_step"] < w["step"]:
            failures.append(f"{w['kind']}: max_step {w['max_step']} before the first crossing {w['step']}")
    if a.source:
        named = [w.get("source") for w in summary["warnings"] if w["kind"] == "energy_error"]
        if named != [a.source]:
            failures.append(f"energy_error source {named}, expected {a.source}")
    with open(os.path.join(a.out, "history.csv")) as f:
        rows = list(csv.reader(f))
    if len(rows) < 2 or rows[0][:2] != ["step", "time"]:
        failures.append("history.csv is not a header and rows")
    elif not all(len(r) == len(rows[0]) and all(not math.isnan(float(v)) for v in r) for r in rows[1:]):
        failures.append("history.csv has a short or non-numeric row")
    with open(os.path.join(a.out, "log.txt")) as f:
        log = f.read()
    said = [line for line in log.splitlines() if line.startswith("warning: ")]
    if len(said) != len(kinds):
        failures.append(f"log.txt has {len(said)} warning lines for {len(kinds)} warnings")
    closing = [line for line in log.splitlines() if "termination" in line and line[:1].isupper()]
    if not closing or a.says not in closing[-1] or (kinds and f"{len(kinds)} warning" not in closing[-1]):
        failures.append(f"closing line {closing[-1:]} lacks '{a.says}' or the warning count")
    for w in summary["warnings"]:
        print(f"  {w['kind']}: {w['message']}")
    return report_failures(failures, ok=f"OK: exit {a.code}, warnings {kinds}, outputs readable")

if __name__ == "__main__":
    sys.exit(main())
