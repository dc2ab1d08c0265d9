#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""A parameter study from Python, notebook style (issue 56 scope 2): the tutorial's deck
(docs/tutorial/first_contact.i) swept over the work of adhesion, the friction and the adhesive pull
read from each run, one table and one plot.

  ./tribex.sh python inputs/examples/python_study/friction_vs_adhesion.py [--out DIR]

(or PYTHONPATH=tools/python /usr/bin/python3 ...; any working directory). About 10 s on 2 cores.
"""
import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "tools" / "python"))
import tribex  # noqa: E402

DECK = pathlib.Path(__file__).resolve().parents[3] / "docs" / "tutorial" / "first_contact.i"

ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
ap.add_argument("--out", default="friction_vs_adhesion_output")
a = ap.parse_args()

# 1. The study: one run per W (the deck's {W}), two at a time; each run's folder keeps its parameters.
def measure(r):
    t = 85e-12  # s: mid-slide (the slide runs 40-90 ps)
    return {"normal_force_N": r.at(t, "contact_normal_force"), "adhesive_force_N": r.at(t, "adhesive_force"),
            "friction_force_N": r.at(t, "friction_force"), "energy_error": r.summary["energy_error"]}


rows = tribex.study(DECK, a.out, "W", ["0 J/m^2", "0.025 J/m^2", "0.05 J/m^2", "0.1 J/m^2"], measure=measure)

# 2. The table: Coulomb friction carries mu (N + F_ad), so F / (N + F_ad) stays at the deck's MU = 0.3.
print(f"{'W (J/m^2)':>10} {'N (nN)':>9} {'F_ad (nN)':>10} {'F (nN)':>9} {'F/(N+F_ad)':>11}")
for r in rows:
    ratio = r["friction_force_N"] / (r["normal_force_N"] + r["adhesive_force_N"])
    print(f"{r['W']:10.3f} {r['normal_force_N'] * 1e9:9.2f} {r['adhesive_force_N'] * 1e9:10.3f} "
          f"{r['friction_force_N'] * 1e9:9.2f} {ratio:11.4f}")
print("table:", tribex.write_table(rows, pathlib.Path(a.out) / "study.csv"))

# 3. A plot of the curves of every run, straight from the Result objects.
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(6.5, 4))
for r in rows:
    res = tribex.load(r["out"])
    ax.plot(res.history["time"] * 1e12, res.history["friction_force"] * 1e9, label=f"W = {r['W']:g} J/m$^2$")
ax.set_xlabel("time (ps)")
ax.set_ylabel("friction force (nN)")
ax.legend()
fig.tight_layout()
fig.savefig(pathlib.Path(a.out) / "friction.png", dpi=120)
print("plot:", pathlib.Path(a.out) / "friction.png")
