#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Sphere sliding on a flat with the junction model (issue 4 acceptance; docs/theory.md 7, 8.2).

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
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from contact_theory import dmt_radius as dmt_radius_of, effective_modulus  # noqa: E402
from history_checks import pyplot, read_history, report_failures, save_figure  # noqa: E402
from sliding_checks import base_reaction_failure, friction_radius_axes, sliding_rows, steady_window  # noqa: E402
from cli_errors import guarded  # noqa: E402

E, NU, R = 161e9, 0.23, 27e-9
ESTAR = effective_modulus(E, NU)
W = 0.05          # J/m^2
TAU_STAR = 195e6  # Pa


def dmt_radius(P):
    return dmt_radius_of(P, R, W, ESTAR)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output")
    ap.add_argument("--window", type=float, nargs=2, required=True, metavar=("S0", "S1"),
                    help="steady window in sliding distance, nm")
    ap.add_argument("--tolerance", type=float, default=0.05)
    ap.add_argument("--plot", help="PNG: friction force and contact radius versus sliding distance")
    a = ap.parse_args()
    rows = read_history(a.output)
    w = steady_window(rows, "x", a.window[0] * 1e-9, a.window[1] * 1e-9)
    failures = []
    if w is None or len(w["rows"]) < 10:
        print(f"FAIL: only {len(w['rows']) if w else 0} history rows with sliding distance in {a.window} nm")
        return 1
    F, P, area, capacity, base = w["F"], w["P"], w["area"], w["capacity"], w["base"]
    a_dmt = dmt_radius(P)
    F_ref = TAU_STAR * math.pi * a_dmt ** 2
    err = F / F_ref - 1
    loads = [r["contact_normal_force"] for r in w["rows"]]
    ke_ie = w["ke_ie"]
    energy_error = max(abs(r["energy_error"]) for r in rows)
    print(f"steady window: sliding distance {a.window[0]:g}-{a.window[1]:g} nm, {len(w['rows'])} rows")
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
    base_failure = base_reaction_failure(w, "x")
    if base_failure:
        failures.append(base_failure)

    if a.plot:
        sliding = sliding_rows(rows, "x")
        s = [r["tip_top_displacement_x"] * 1e9 for r in sliding]
        fig, (ax1, ax2) = friction_radius_axes(pyplot())
        ax1.plot(s, [r["friction_force"] * 1e9 for r in sliding], label="friction force (FE)")
        ax1.plot(s, [TAU_STAR * math.pi * dmt_radius(r["contact_normal_force"]) ** 2 * 1e9 for r in sliding], "k--",
                 label=r"$\tau^* \pi a_{DMT}^2$ at the FE load")
        ax1.plot(s, [r["tau_star_times_area"] * 1e9 for r in sliding], ":", label=r"$\tau^*$ x FE contact area")
        ax1.axvspan(a.window[0], a.window[1], color="0.9", label="steady window")
        ax1.set_ylabel("friction force (nN)")
        ax1.set_ylim(bottom=0)
        ax1.legend(fontsize=8, loc="lower right")
        ax2.plot(s, [math.sqrt(r["contact_area"] / math.pi) * 1e9 for r in sliding], label=r"FE $\sqrt{A/\pi}$")
        ax2.plot(s, [dmt_radius(r["contact_normal_force"]) * 1e9 for r in sliding], "k--", label="DMT at the FE load")
        ax2.axvspan(a.window[0], a.window[1], color="0.9")
        ax2.set_xlabel("sliding distance (nm)")
        ax2.set_ylabel("contact radius (nm)")
        ax2.legend(fontsize=8, loc="lower right")
        fig.suptitle(r"Si sphere R = 27 nm on Si, W = 0.05 J/m$^2$, $\tau^*$ = 195 MPa", fontsize=10)
        save_figure(fig, a.plot)

    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(guarded(main))
