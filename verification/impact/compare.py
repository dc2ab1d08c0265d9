#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Impact of two free blocks (verification/impact/impact.i): conservation checks.

Tolerances (issue "Contact"): total energy (kinetic + internal + energy held or lost in contact)
within 1 % of the initial kinetic energy at every output; total momentum conserved to round-off
(relative change below 1e-12); the falling block must touch (contact force > 0 at some output) and
rebound (its mean z velocity, from the mean displacement history, ends positive).
"""
import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import finish_axes, pyplot, read_history, save_figure  # noqa: E402
from cli_errors import guarded  # noqa: E402


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("history")
    p.add_argument("--plot")
    a = p.parse_args()
    rows = read_history(a.history)
    ke0 = rows[0]["kinetic_energy"]
    worst = max(abs(r["kinetic_energy"] + r["internal_energy"] + r["hourglass_energy"] +
                    r["contact_work"] + r["viscous_dissipation"] - ke0) / ke0 for r in rows)
    pz0 = rows[0]["momentum_z"]
    drift = max(abs(r["momentum_z"] - pz0) for r in rows) / abs(pz0)
    dxy = max(abs(r["momentum_x"]) + abs(r["momentum_y"]) for r in rows) / abs(pz0)
    touched = max(r["contact_normal_force"] for r in rows)
    z = [r["top_all_displacement_z"] for r in rows]
    t = [r["time"] for r in rows]
    v_end = (z[-1] - z[-4]) / (t[-1] - t[-4])
    ok = worst < 0.01 and drift < 1e-12 and dxy < 1e-12 and touched > 0 and v_end > 0
    print(f"energy: worst |E - E0| / E0 = {worst:.2e} (tolerance 1e-2)")
    print(f"momentum: relative drift in z {drift:.2e}, x+y {dxy:.2e} (tolerance 1e-12)")
    print(f"peak contact force {touched * 1e9:.1f} nN; mean velocity of the upper block at the end {v_end:.1f} m/s "
          f"(rebound: > 0)")
    print(f"energy left in the contact at the end: {rows[-1]['contact_work'] / ke0:.2%} of the impact energy")
    print("PASS" if ok else "FAIL")
    if a.plot:
        fig, ax = pyplot().subplots(figsize=(6, 4))
        ps = [x * 1e12 for x in t]
        for k in ("kinetic_energy", "internal_energy", "contact_work"):
            ax.plot(ps, [r[k] / ke0 for r in rows], label=k.replace("_", " "))
        finish_axes(ax, "time (ps)", "energy / initial kinetic energy")
        save_figure(fig, a.plot, announce=None)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(guarded(main))
