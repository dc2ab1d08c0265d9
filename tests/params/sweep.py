#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""A parameter sweep through `tribex run DECK --set W=...` (issue 56 scope 1, inputs/README.md "Parameters").

Runs tests/params/sweep_dmt.i three times, W = 0, 0.05, 0.1 J/m^2, and once as its W = 0 twin with
`model = frictionless`; writes OUT/sweep.csv (one row per W: the adhesive force and the normal forces,
means over the hold 30-40 ps) and checks:
  - each run's summary.json "parameters" and log.txt "parameters:" line give the W it was set to;
  - W = 0: no adhesive force, and the same history as model = frictionless (every column both have,
    relative 1e-12: the adhesion law with W = 0 is penalty contact only, with frictionless contact's search);
  - the adhesive force scales with W: F_ad(0.1) / F_ad(0.05) = 2 within 5 % (DMT, docs/theory.md 8.2:
    the attraction outside the contact is 2 pi R W, linear in W while the Tabor parameter is small;
    measured 1.951, the doubled W raises the Tabor parameter mu_T ~ W^(2/3) and the contact grows a little;
    between 0.025 and 0.05 J/m^2 the ratio is 1.978).
The ratio F_ad / (2 pi R W) is in the table, not checked: 1.45 on this 1.6 nm mesh (z0 = 0.3 nm is not resolved;
verification/dmt checks the pull-off on finer meshes).

Usage: /usr/bin/python3 tests/params/sweep.py TRIBEX DECK OUT
"""
import csv
import json
import math
import os
import re
import subprocess
import sys

SWEEP = [0.0, 0.05, 0.1]  # J/m^2
HOLD_START = 30e-12  # s: the push ends at 30 ps, then the tip is held
RADIUS = 27e-9  # m, the deck's {R}
COMPARED = ["time", "dt", "kinetic_energy", "internal_energy", "external_work", "contact_work", "contact_normal_force",
            "compressive_force", "tip_top_reaction_z", "substrate_bottom_reaction_z", "tip_apex_displacement_z"]


def run(tribex, deck, out, *extra):
    cmd = [tribex, "run", deck, "-o", out, "--quiet", *extra]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit("FAIL: %s exited %d:\n%s%s" % (" ".join(cmd), done.returncode, done.stdout, done.stderr))
    with open(os.path.join(out, "history.csv")) as f:
        return list(csv.DictReader(f))


def hold_mean(rows, column):
    values = [float(r[column]) for r in rows if float(r["time"]) >= HOLD_START * (1 - 1e-9)]
    return sum(values) / len(values)


def check_echo(out, w, failures):
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    if summary.get("parameters", {}).get("W") != w or summary["units"]["parameters"].get("W") != "J/m^2":
        failures.append("%s/summary.json: parameters %s, units %s; expected W = %g J/m^2"
                        % (out, summary.get("parameters"), summary["units"].get("parameters"), w))
    with open(os.path.join(out, "log.txt")) as f:
        log = f.read()
    m = re.search(r"^parameters: W = (\S+) J/m\^2 \(--set\), R = 2\.7e-08 m$", log, re.M)
    if not m or float(m.group(1)) != w:
        failures.append("%s/log.txt: no line 'parameters: W = %g J/m^2 (--set), R = 2.7e-08 m'" % (out, w))


def same_history(a, b, failures):
    if len(a) != len(b):
        return failures.append("W = 0 and frictionless: %d and %d history rows" % (len(a), len(b)))
    worst = 0.0
    for ra, rb in zip(a, b):
        for c in COMPARED:
            x, y = float(ra[c]), float(rb[c])
            scale = max(abs(float(r[c])) for r in a) or 1.0
            worst = max(worst, abs(x - y) / scale)
    print("W = 0 against model = frictionless: largest difference %.3g of the column's largest value "
          "(%d rows, %d columns)" % (worst, len(a), len(COMPARED)))
    if worst > 1e-12:
        failures.append("W = 0 differs from model = frictionless by %.3g (limit 1e-12)" % worst)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    tribex, deck, out = sys.argv[1:]
    os.makedirs(out, exist_ok=True)
    failures = []
    table = []
    histories = {}
    for w in SWEEP:
        folder = os.path.join(out, "W_%g" % w)
        rows = histories[w] = run(tribex, deck, folder, "--set", "W=%r" % w)
        check_echo(folder, w, failures)
        f_ad = hold_mean(rows, "adhesive_force")
        table.append([w, f_ad, hold_mean(rows, "compressive_force"), hold_mean(rows, "contact_normal_force"),
                      f_ad / (2 * math.pi * RADIUS * w) if w > 0 else float("nan")])
    # The W = 0 twin: the same deck with model = frictionless and no adhesion keys.
    with open(deck) as f:
        text = f.read()
    text = re.sub(r"model = adhesion\n(\s*work of adhesion.*\n)(\s*equilibrium separation.*\n)(\s*adhesion cutoff.*\n)",
                  "model = frictionless\n", text)
    twin = os.path.join(out, "sweep_dmt_frictionless.i")
    with open(twin, "w") as f:
        f.write(text)
    same_history(histories[0.0], run(tribex, twin, os.path.join(out, "frictionless")), failures)
    if any(float(r["adhesive_force"]) != 0.0 for r in histories[0.0]):
        failures.append("W = 0: adhesive_force is not 0 on every row")

    with open(os.path.join(out, "sweep.csv"), "w", newline="") as f:
        w_csv = csv.writer(f)
        w_csv.writerow(["work_of_adhesion[J/m^2]", "adhesive_force[N]", "compressive_force[N]",
                        "contact_normal_force[N]", "adhesive_force_over_2piRW[-]"])
        for row in table:
            w_csv.writerow(["%r" % row[0]] + ["%.9g" % v for v in row[1:]])
    for row in table:
        print("W = %-5g J/m^2: adhesive force %.5g N, compressive %.5g N, net normal %.5g N, F_ad/(2 pi R W) %.4g"
              % tuple(row))
    ratio = table[2][1] / table[1][1]
    print("F_ad(W = 0.1) / F_ad(W = 0.05) = %.4f (expected 2 within 5 %%)" % ratio)
    if abs(ratio / 2 - 1) > 0.05:
        failures.append("F_ad(0.1)/F_ad(0.05) = %.4f, not 2 within 5 %%" % ratio)
    print("table: %s" % os.path.join(out, "sweep.csv"))
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
