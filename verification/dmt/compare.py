#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""DMT check of an adhesive asperity indentation (verification/dmt/*.i).

Reference (docs/theory.md 8.2): a^3 = 3R(P + 2 pi W R)/(4E*), pull-off P_c = -2 pi W R, with
E* = E/(2(1 - nu^2)) = 85.0 GPa, R = 27 nm, W = 0.05 J/m^2 (Tabor mu_T = 0.070 for z0 = 0.3 nm,
so the Maugis-Dugdale pull-off is 1.95 pi W R, between DMT's 2 and the JKR 1.5).
Measured: P = contact_normal_force (compressive minus adhesive: the load the tip applies);
a = --radius pressure_fit (default): contact_radius_pressure_fit, the zero of the least-squares line
p^2 = alpha - beta r^2 through the contacting nodes' compressive (penalty) pressures, whose shape in
the DMT limit is Hertz's at the load P + 2 pi W R (see verification/hertz/README.md); --radius edge:
contact_radius_edge (gap sign change along the tip-surface edges, interpolated between nodes);
--radius area: contact_radius_area, sqrt(contact_area/pi); --radius plain: contact_radius (the edge
estimate here: the deck has a contact axis).
Compared: loading branch, at loads whose DMT radius a_D(P) is at least 5 element sizes and at most
R/4 (rows chosen by the load, not by the radius under test): a within the tolerance of a_D; pull-off = the most negative P during withdrawal, within
the tolerance of 2 pi W R. With W = 0 the same comparison is the Hertz one (--work-of-adhesion 0).
Energy balance: the history's energy_error (|kinetic + internal + dissipated + contact work - external
work| over the largest energy of the run, solver/energy.hpp; the contact work is that of the penalty,
adhesive and junction forces, so the adhesive energy and any frictional dissipation are in it) must
stay within --energy-tolerance (1 %) at every recorded time of the run, loading and withdrawal.
"""
import argparse
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from cli_errors import guarded  # noqa: E402
from contact_theory import (RADIUS_ESTIMATORS, dmt_radius, effective_modulus, print_unchecked_radius,  # noqa: E402
                            radius_column)
from history_checks import (deepest_index, finish_axes, max_and_mean, model_fraction, pyplot,  # noqa: E402
                            radius_errors, read_full_history, save_figure)

E, NU, R = 161e9, 0.23, 27e-9
ESTAR = effective_modulus(E, NU)


def branches(rows, column):
    """(P, a) of the loading branch (to the deepest tip position) and of the withdrawal, in nN and nm,
    where the contact has a radius."""
    deepest = deepest_index(rows)
    pick = lambda part: [(r["contact_normal_force"] * 1e9, r[column] * 1e9) for r in part if r[column] > 0]  # noqa: E731
    return pick(rows[: deepest + 1]), pick(rows[deepest + 1:])


def plot(a, rows, column, W, Pc, pull_off, h):
    """a(P) of every recorded time, loading (filled) and withdrawal (open), for W and, with
    --hertz-output, the W = 0 twin, against DMT and Hertz; radii under 5 element sizes shaded."""
    fig, ax = pyplot().subplots(figsize=(7, 5))
    load, unload = branches(rows, column)
    top = max(p for p, _ in load)
    grid = [Pc + (top * 1e-9 - Pc) * i / 400 for i in range(401)]
    ax.plot([x * 1e9 for x in grid], [dmt_radius(x, R, W, ESTAR) * 1e9 for x in grid], "k-",
            label="DMT, W = %.2f J/m$^2$" % W)
    gh = [x for x in grid if x >= 0]
    ax.plot([x * 1e9 for x in gh], [dmt_radius(x, R, 0.0, ESTAR) * 1e9 for x in gh], "k--", label="Hertz (W = 0)")
    runs = [(f"W = {W:.2f} J/m$^2$", load, unload, "o", "C0")]
    if a.hertz_output:
        runs.append(("W = 0",) + branches(read_full_history(a.hertz_output), column) + ("s", "C1"))
    for name, up, down, marker, colour in runs:
        for pts, fill, what in ((up, colour, "loading"), (down, "none", "withdrawal")):
            ax.plot([x for x, _ in pts], [y for _, y in pts], marker, ms=3.5, mfc=fill, mec=colour,
                    label=f"FE {name}, {what}")
    ax.axhspan(0, 5 * h * 1e9, color="0.9", zorder=0, label="a under 5 elements (mesh-limited)")
    if W > 0:
        ax.axvline(pull_off * 1e9, color="r", lw=0.9, label=f"FE pull-off {pull_off * 1e9:.2f} nN")
        ax.axvline(Pc * 1e9, color="r", lw=0.9, ls=":", label=f"DMT pull-off -2$\\pi$WR = {Pc * 1e9:.2f} nN")
    ax.set_xlim(Pc * 1e9 * 1.3, top * 1.02)
    ax.set_ylim(0, None)
    finish_axes(ax, "applied load P (nN)", "contact radius a (nm)",
                f"silicon sphere R = {R * 1e9:.0f} nm on a silicon flat: contact radius against load")
    save_figure(fig, a.plot)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("output")
    p.add_argument("--element-size", type=float, required=True, help="nm")
    p.add_argument("--work-of-adhesion", type=float, default=0.05, help="J/m^2")
    p.add_argument("--tolerance", type=float, default=0.05)
    p.add_argument("--radius", choices=RADIUS_ESTIMATORS, default="pressure_fit",
                   help="contact-radius estimator checked: pressure_fit, edge, area (history column "
                        "contact_radius_<this>) or plain (contact_radius)")
    p.add_argument("--energy-tolerance", type=float, default=0.01, help="largest |energy_error| allowed")
    p.add_argument("--plot")
    p.add_argument("--hertz-output", help="output folder of the W = 0 run (verification/hertz) to draw beside")
    a = p.parse_args()
    W = a.work_of_adhesion
    rows = read_full_history(a.output)  # a quarter model's forces and energies times 4 (its log.txt says which it is)
    h = a.element_size * 1e-9
    # Loading branch: up to the deepest tip position.
    deepest = deepest_index(rows)
    column = radius_column(a.radius)
    radius = lambda P: dmt_radius(P, R, W, ESTAR)  # noqa: E731
    used = [r for r in rows[: deepest + 1]
            if 5 * h <= radius(r["contact_normal_force"]) <= 0.25 * R]
    if len(used) < 5:
        print(f"FAIL: only {len(used)} usable loading rows (need loads whose DMT radius is between 5 element sizes and R/4)")
        return 1
    P, _, aD, ea = radius_errors(used, column, radius)
    worst = max(range(len(ea)), key=lambda i: ea[i])
    pull_off = min(r["contact_normal_force"] for r in rows[deepest:])
    Pc = -2 * math.pi * W * R
    ep = abs(pull_off - Pc) / abs(Pc) if W > 0 else 0.0
    energy_error = max(abs(r["energy_error"]) for r in rows)
    ok = len(used) >= 5 and max(ea) <= a.tolerance and ep <= a.tolerance and energy_error <= a.energy_tolerance
    if model_fraction(a.output) != 1.0:
        print("quarter model (symmetry = quarter): forces, areas and energies times 4")
    print(f"W = {W} J/m^2, 2 pi W R = {-Pc * 1e9:.3f} nN; {len(used)} loads from {P[0] * 1e9:.1f} to {P[-1] * 1e9:.1f} nN")
    max_ea, mean_ea = max_and_mean(ea)
    print(f"contact radius ({column}) vs DMT at P + 2 pi W R: max error {max_ea:.2%} at {P[worst] * 1e9:.1f} nN "
          f"(a_D = {aD[worst] * 1e9:.2f} nm), mean {mean_ea:.2%}; tolerance {a.tolerance:.0%}")
    print_unchecked_radius(used, aD, a.radius)
    if W > 0:
        print(f"pull-off {pull_off * 1e9:.3f} nN vs -2 pi W R = {Pc * 1e9:.3f} nN: error {ep:.2%}; tolerance {a.tolerance:.0%}")
    print(f"energy balance: max |energy_error| {energy_error:.3%} over the run (adhesion energy at the end "
          f"{rows[-1]['adhesion_energy']:.3g} J, contact work {rows[-1]['contact_work']:.3g} J); "
          f"tolerance {a.energy_tolerance:.0%}")
    print("PASS" if ok else "FAIL")
    if a.plot:
        plot(a, rows, column, W, Pc, pull_off, h)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(guarded(main))
