#!/usr/bin/env python3
"""Pull-off of a mass-scaled DMT run against the same deck unscaled (issue 24: within 2 %).

Pull-off = the most negative contact normal force after the deepest tip position (as compare.py), of the
full problem (a quarter model's, read from its log.txt, times 4).
Usage: compare_pull_off.py SCALED_OUTPUT UNSCALED_OUTPUT [--tolerance 0.02]
"""
import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import deepest_index, read_full_history  # noqa: E402
from cli_errors import guarded  # noqa: E402


def pull_off(output):
    rows = read_full_history(output)  # a quarter model's force times 4: either run may be one
    return min(r["contact_normal_force"] for r in rows[deepest_index(rows):])


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("scaled")
    p.add_argument("unscaled")
    p.add_argument("--tolerance", type=float, default=0.02)
    a = p.parse_args()
    scaled, unscaled = pull_off(a.scaled), pull_off(a.unscaled)
    err = abs(scaled - unscaled) / abs(unscaled)
    ok = err <= a.tolerance
    print(f"pull-off {scaled * 1e9:.4f} nN (mass scaled) vs {unscaled * 1e9:.4f} nN (unscaled): "
          f"difference {err:.2%}; tolerance {a.tolerance:.0%}: {'PASS' if ok else 'FAIL'}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(guarded(main))
