#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Sphere sliding on a flat with the junction model (issue 4 acceptance; physics.md 7, 8.2).

Reference: steady friction F = tau* pi a^2 with a the DMT contact radius at the applied load,
a^3 = 3 R (P + 2 pi W R) / (4 E*), E* = E / (2 (1 - nu^2)) = 85.0 GPa, R = 27 nm, W = 0.05 J/m^2,
tau* = 195 MPa.
Measured, as means over the steady window (sliding distance s = tip-top x displacement in
[--window S0 S1] nm): F = friction_force (magnitude of the summed junction shear on the tip
surface), P = contact_normal_force (compressive minus adhesive: the load the tip applies; held by
a displacement hold of the tip top, so it is measured, not prescribed).
Checked: |F / (tau* pi a_DMT^2) - 1| <= --tolerance; kinetic energy below 2 % of internal energy in
the window (quasi-static); the substrate's base reaction opposes the friction on the substrate.
Also printed: the FE contact radius sqrt(A/pi) against a_DMT, F against tau* x (FE contact area)
(1 when every contacting node slips), the normal-load drift over the window, the energy error.

usage: compare.py OUTPUT_DIR --window S0 S1 [--tolerance 0.05] [--plot OUT.png]
"""
import argparse
import csv
import math
import sys

E, NU, R = 161e9, 0.23, 27e-9
ESTAR = E / (2 * (1 - NU * NU))
W = 0.05          # J/m^2
TAU_STAR = 195e6  # Pa


def dmt_radius(P):
    return (3 * R * max(P + 2 * math.pi * W * R, 0.0) / (4 * ESTAR)) ** (1 / 3)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("output")
    ap.add_argument("--window", type=float, nargs=2, required=True, metavar=("S0", "S1"),
                    help="steady window in sliding distance, nm")
    ap.add_argument("--tolerance", type=float, default=0.05)
    ap.add_argument("--plot", help="PNG: friction force and contact radius versus sliding distance")
    a = ap.parse_args()
    with open(f"{a.output}/history.csv") as f:
        rows = list(csv.DictReader(f))
    val = lambda r, k: float(r[k])  # noqa: E731
    s0, s1 = a.window[0] * 1e-9, a.window[1] * 1e-9
    window = [r for r in rows if s0 <= val(r, "tip_top_displacement_x") <= s1]
    failures = []
    if len(window) < 10:
        print(f"FAIL: only {len(window)} history rows with sliding distance in {a.window} nm")
        return 1
    mean = lambda k: sum(val(r, k) for r in window) / len(window)  # noqa: E731
    F = mean("friction_force")
    P = mean("contact_normal_force")
    area = mean("contact_area")
    capacity = mean("tau_star_times_area")
    base = mean("substrate_bottom_reaction_x")
    a_dmt = dmt_radius(P)
    F_ref = TAU_STAR * math.pi * a_dmt ** 2
    err = F / F_ref - 1
    loads = [val(r, "contact_normal_force") for r in window]
    ke_ie = max(val(r, "kinetic_energy") / val(r, "internal_energy") for r in window)
    energy_error = max(abs(val(r, "energy_error")) for r in rows)
    print(f"steady window: sliding distance {a.window[0]:g}-{a.window[1]:g} nm, {len(window)} rows")
    print(f"normal load P = {P * 1e9:.2f} nN (drift over the window {(max(loads) - min(loads)) / P:.2%}); "
          f"DMT a = {a_dmt * 1e9:.3f} nm, a/R = {a_dmt / R:.3f}")
    print(f"friction F = {F * 1e9:.3f} nN vs tau* pi a_DMT^2 = {F_ref * 1e9:.3f} nN: error {err:+.2%} "
          f"(tolerance {a.tolerance:.0%})")
    print(f"FE contact radius sqrt(A/pi) = {math.sqrt(area / math.pi) * 1e9:.3f} nm ({math.sqrt(area / math.pi) / a_dmt - 1:+.2%} "
          f"vs DMT); F / (tau* A_FE) = {F / capacity:.4f}")
    print(f"base reaction x {base * 1e9:.3f} nN; max KE/IE in the window {ke_ie:.2%}; "
          f"max |energy error| over the run {energy_error:.2e}")
    if abs(err) > a.tolerance:
        failures.append(f"friction differs from tau* pi a_DMT^2 by {err:+.2%} (> {a.tolerance:.0%})")
    if ke_ie > 0.02:
        failures.append(f"kinetic energy up to {ke_ie:.2%} of internal in the window (> 2 %): not quasi-static")
    if not base < -0.5 * F:
        failures.append(f"base reaction x {base:.4g} N does not oppose the friction dragging the substrate in +x")

    if a.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        sliding = [r for r in rows if val(r, "tip_top_displacement_x") > 1e-13]
        s = [val(r, "tip_top_displacement_x") * 1e9 for r in sliding]
        fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6, 6), sharex=True)
        ax1.plot(s, [val(r, "friction_force") * 1e9 for r in sliding], label="friction force (FE)")
        ax1.plot(s, [TAU_STAR * math.pi * dmt_radius(val(r, "contact_normal_force")) ** 2 * 1e9 for r in sliding], "k--",
                 label=r"$\tau^* \pi a_{DMT}^2$ at the FE load")
        ax1.plot(s, [val(r, "tau_star_times_area") * 1e9 for r in sliding], ":", label=r"$\tau^*$ x FE contact area")
        ax1.axvspan(a.window[0], a.window[1], color="0.9", label="steady window")
        ax1.set_ylabel("friction force (nN)")
        ax1.set_ylim(bottom=0)
        ax1.legend(fontsize=8, loc="lower right")
        ax2.plot(s, [math.sqrt(val(r, "contact_area") / math.pi) * 1e9 for r in sliding], label=r"FE $\sqrt{A/\pi}$")
        ax2.plot(s, [dmt_radius(val(r, "contact_normal_force")) * 1e9 for r in sliding], "k--", label="DMT at the FE load")
        ax2.axvspan(a.window[0], a.window[1], color="0.9")
        ax2.set_xlabel("sliding distance (nm)")
        ax2.set_ylabel("contact radius (nm)")
        ax2.legend(fontsize=8, loc="lower right")
        fig.suptitle(r"Si sphere R = 27 nm on Si, W = 0.05 J/m$^2$, $\tau^*$ = 195 MPa", fontsize=10)
        fig.tight_layout()
        fig.savefig(a.plot, dpi=120)
        print(f"plot: {a.plot}")

    for line in failures:
        print("FAIL:", line)
    print("PASS" if not failures else "FAIL")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
