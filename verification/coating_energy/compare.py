#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Energy balance of a soft-coating indentation run (verification/coating_energy/README.md).

Reads the run's history.csv and checks that |energy_error| stays within the tolerance on every row
(the whole push, hold and withdrawal), and that the contact's net work over the closed cycle is
small against the largest internal energy (a conservative contact returns what it stored).
Prints the figures and PASS, or FAIL with the worst row; exit 1 on FAIL.

usage: compare.py OUTPUT_FOLDER [--tolerance 0.005]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "python"))
from history_checks import read_history  # noqa: E402
from cli_errors import guarded  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output", help="the run's output folder (holds history.csv)")
    ap.add_argument("--tolerance", type=float, default=0.005, help="largest |energy_error| accepted (default 0.005)")
    a = ap.parse_args()
    rows = read_history(a.output)
    worst = max(rows, key=lambda r: abs(r["energy_error"]))
    ie_max = max(r["internal_energy"] for r in rows)
    name = os.path.basename(os.path.normpath(a.output))
    print(f"{name}: {len(rows)} rows to t = {rows[-1]['time'] * 1e12:.0f} ps; max |energy_error| "
          f"{abs(worst['energy_error']):.3e} at t = {worst['time'] * 1e12:.0f} ps (tolerance {a.tolerance:g}); "
          f"at the end {rows[-1]['energy_error']:.3e}; contact work at the end {rows[-1]['contact_work']:.3e} J "
          f"(largest internal energy {ie_max:.3e} J); largest penetration "
          f"{max(r['contact_max_penetration'] for r in rows) * 1e9:.4f} nm")
    with open(os.path.join(a.output, "summary.json")) as f:
        summary = json.load(f)
    if summary.get("exit_code") != 0:  # a run stopped early holds too few rows to judge
        print(f"FAIL: the run ended with exit code {summary.get('exit_code')} ({summary.get('status')})")
        return 1
    if abs(worst["energy_error"]) > a.tolerance:
        print(f"FAIL: |energy_error| {abs(worst['energy_error']):.3e} > {a.tolerance:g}")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(guarded(main))
