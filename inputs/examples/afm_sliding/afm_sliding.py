#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""AFM sliding example (the report's Section 3.5, Fig. 3.9): runs case (a) Si on Si and case (b) Si on
a 2 nm SAM of one variant (decks written by make_decks.py), checks them, prints the cost figures
and plots friction force and contact radius against the sliding position.

Checked for each case (all from history.csv; the tolerances are stated, not tuned):
  * load control: the contact normal force (compressive minus adhesive, the load the tip applies)
    averaged over the last 20 ps of the hold is 500 nN within 2 %;
  * quasi-static hold: kinetic energy below 1 % of internal energy over the last 20 ps of the hold;
  * steady sliding (sliding distance >= 1 nm, after the 40 ps speed ramp): friction force = tau* x
    FE contact area (every contacting pair slips: the junction shear saturates at tau*,
    tanh(V / v_ref) = tanh(75)) within 2 % at every history row, and its mean within 1 %;
  * sign: the substrate's base reaction in y opposes the friction that drags the substrate in +y
    (mean base reaction y < -0.5 F);
  * (b) against (a): the compliant SAM gives the larger contact radius (the report's Fig. 3.9).
Printed: wall time, elements, steps and ns per element per step (from summary.json), the mean
friction, the FE contact radius sqrt(A/pi) and the DMT radius of a 50 nm sphere on a flat at the same
load (a reference only for case (a): the AFM surface is curved and tilted under the tip).

usage: afm_sliding.py [--tribex build/bin/tribex] [--variant reduced|full] [--out DIR] [--plot PNG]
                      [--no-run]   (--no-run: check outputs already in DIR/<deck>_output)
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
LOAD = 500e-9                      # N, as in make_decks.py
HOLD_END = (120e-12, 140e-12)      # s: last 20 ps of the hold (load ramp 0-80 ps, hold 80-140 ps)
STEADY_FROM = 1.0e-9               # m of sliding
R_TIP = 50e-9
W = 0.05                           # J/m^2
CASES = [("a_si", "(a) Si on Si", 195e6), ("b_sam", "(b) Si on 2 nm SAM", 194e6)]


def dmt_radius_si(P):
    """DMT radius of the Si sphere on a flat Si half-space: a^3 = 3 R (P + 2 pi W R) / (4 E*)."""
    estar = 161e9 / (2 * (1 - 0.23 ** 2))
    return (3 * R_TIP * max(P + 2 * math.pi * W * R_TIP, 0.0) / (4 * estar)) ** (1 / 3)


def check_case(folder, label, tau):
    with open(os.path.join(folder, "history.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    failures = []
    hold = [r for r in rows if HOLD_END[0] <= r["time"] <= HOLD_END[1]]
    steady = [r for r in rows if r["tip_top_displacement_y"] >= STEADY_FROM]
    if len(hold) < 5 or len(steady) < 5:
        return None, [f"{label}: too few history rows in the hold ({len(hold)}) or steady sliding ({len(steady)})"]
    mean = lambda rs, k: sum(r[k] for r in rs) / len(rs)  # noqa: E731
    P_hold = mean(hold, "contact_normal_force")
    ke_ie = max(r["kinetic_energy"] / r["internal_energy"] for r in hold)
    F = mean(steady, "friction_force")
    cap = mean(steady, "tau_star_times_area")
    worst = max(abs(r["friction_force"] / r["tau_star_times_area"] - 1) for r in steady)
    A = mean(steady, "contact_area")
    P = mean(steady, "contact_normal_force")
    base_y = mean(steady, "substrate_bottom_reaction_y")
    a_fe = math.sqrt(A / math.pi)
    print(f"{label}: {summary['elements']} hex8, {summary['steps']} steps, {summary['wall_time_s']:.1f} s wall, "
          f"{summary['ns_per_element_step']:.0f} ns/element/step (wall times are noisy on a shared machine)")
    print(f"  hold: P = {P_hold * 1e9:.2f} nN (load {LOAD * 1e9:.0f} nN, tolerance 2 %), max KE/IE {ke_ie:.2e} (limit 1 %)")
    print(f"  sliding {STEADY_FROM * 1e9:g}-{steady[-1]['tip_top_displacement_y'] * 1e9:.2f} nm ({len(steady)} rows): "
          f"F = {F * 1e9:.3f} nN, tau* A_FE = {cap * 1e9:.3f} nN, F / (tau* A) - 1 = {F / cap - 1:+.3%} (tolerance 1 %), "
          f"worst row {worst:.3%} (tolerance 2 %)")
    print(f"  P = {P * 1e9:.2f} nN, FE contact radius sqrt(A/pi) = {a_fe * 1e9:.3f} nm "
          f"(Si sphere on a flat Si, DMT: {dmt_radius_si(P) * 1e9:.3f} nm); base reaction y {base_y * 1e9:.3f} nN")
    if abs(P_hold / LOAD - 1) > 0.02:
        failures.append(f"{label}: normal load {P_hold * 1e9:.2f} nN at the end of the hold is not 500 nN within 2 %")
    if ke_ie > 0.01:
        failures.append(f"{label}: kinetic energy up to {ke_ie:.2%} of internal in the hold (> 1 %)")
    if abs(F / cap - 1) > 0.01 or worst > 0.02:
        failures.append(f"{label}: friction differs from tau* x contact area (mean {F / cap - 1:+.2%}, worst {worst:.2%})")
    if not base_y < -0.5 * F:
        failures.append(f"{label}: base reaction y {base_y:.4g} N does not oppose the friction dragging the substrate in +y")
    return {"rows": rows, "a_fe": a_fe, "F": F}, failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tribex", default="build/bin/tribex")
    ap.add_argument("--variant", choices=["reduced", "full"], default="reduced")
    ap.add_argument("--out", default="afm_sliding_output")
    ap.add_argument("--plot", help="PNG: friction force and contact radius versus sliding position (Fig. 3.9)")
    ap.add_argument("--no-run", action="store_true", help="only check the outputs already in --out")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    results, failures = {}, []
    for case, label, tau in CASES:
        name = f"afm_sliding_{a.variant}_{case}"
        folder = os.path.join(a.out, name + "_output")
        if not a.no_run:
            subprocess.run([a.tribex, "run", os.path.join(HERE, name + ".i"), "-o", folder, "--quiet"], check=True)
        res, fail = check_case(folder, label, tau)
        failures += fail
        if res:
            results[case] = res
    if len(results) == 2:
        ra, rb = results["a_si"]["a_fe"], results["b_sam"]["a_fe"]
        print(f"contact radius: SAM {rb * 1e9:.3f} nm vs Si {ra * 1e9:.3f} nm (ratio {rb / ra:.3f}; expected > 1)")
        if not rb > ra:
            failures.append("the SAM case does not give the larger contact radius")
    if a.plot and results:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6, 6), sharex=True)
        for case, label, tau in CASES:
            if case not in results:
                continue
            rows = [r for r in results[case]["rows"] if r["tip_top_displacement_y"] > 1e-13]
            s = [r["tip_top_displacement_y"] * 1e9 for r in rows]
            ax1.plot(s, [r["friction_force"] * 1e9 for r in rows], label=f"{label}: friction (FE)")
            ax1.plot(s, [r["tau_star_times_area"] * 1e9 for r in rows], ":", color="k", lw=0.8)
            ax2.plot(s, [math.sqrt(r["contact_area"] / math.pi) * 1e9 for r in rows], label=label)
        ax1.plot([], [], ":", color="k", lw=0.8, label=r"$\tau^*$ x FE contact area")
        ax1.set_ylabel("friction force (nN)")
        ax1.set_ylim(bottom=0)
        ax1.legend(fontsize=8, loc="lower right")
        ax2.set_xlabel("sliding position along the track (nm)")
        ax2.set_ylabel(r"contact radius $\sqrt{A/\pi}$ (nm)")
        ax2.set_ylim(bottom=0)
        ax2.legend(fontsize=8, loc="lower right")
        fig.suptitle(f"Si sphere R = 50 nm, 500 nN, 7.5 m/s on the di-3 AFM surface ({a.variant})", fontsize=10)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
        print(f"plot: {a.plot}")
    for line in failures:
        print("FAIL:", line)
    print("PASS" if not failures else "FAIL")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
