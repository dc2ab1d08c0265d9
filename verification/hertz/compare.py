#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Hertz check of an asperity indentation run (verification/hertz/*.i) against
a^3 = 3PR/(4E*), delta = a^2/R, E* = E/(2(1 - nu^2)) for two identical bodies (silicon, R = 27 nm, by
default; --tip-radius, --youngs-modulus and --poissons-ratio for another deck such as hertz_rescaled.i).

Measured quantities (history.csv):
  P      contact_normal_force (the force the contact transmits);
  a      --radius pressure_fit (default): contact_radius_pressure_fit, the zero of the least-squares
         line p^2 = alpha - beta r^2 through the contacting nodes' pressures (exact for Hertz's
         elliptic pressure; contact/contact_radius.cpp); --radius edge: contact_radius_edge, the mean
         distance from the axis of the points where the gap changes sign along the tip-surface edges
         (linear interpolation between nodes); --radius area: contact_radius_area, sqrt(contact_area/pi),
         which jumps by about a node spacing as each ring enters; --radius plain: contact_radius, the
         column a user reads first (the edge estimate, these decks having a contact axis). The other
         estimators' errors are printed; the first three are plotted;
  delta  -tip_top_displacement_z (the substrate bottom is fixed) minus the penalty overlap at the
         centre (contact_max_penetration), minus C P: the finite column and block add a linear
         far-field compliance C that Hertz's half-spaces do not have. C is fitted by least squares
         over the compared loads; what is checked is the nonlinear P^(2/3) Hertz part.
Compared rows: the loading branch, at loads whose Hertz radius a_H(P) is at least --min-radius (default
5 element sizes: past the first contacting rings) and at most R/4. Selecting by load, not by the
measured radius, keeps the estimator under test out of the choice of rows.
Quasi-static check: kinetic energy below 2 % of internal energy on those rows.
"""
import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from cli_errors import guarded  # noqa: E402
from contact_theory import (RADIUS_ESTIMATORS, dmt_radius, effective_modulus, print_unchecked_radius,  # noqa: E402
                            radius_column)
from history_checks import (max_and_mean, max_kinetic_over_stored, model_fraction, pyplot,  # noqa: E402
                            radius_errors, read_full_history, relative_errors, save_figure)



def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("output", help="the run's output folder")
    p.add_argument("--element-size", type=float, required=True, help="element size at the contact, nm")
    p.add_argument("--tolerance", type=float, default=0.03)
    p.add_argument("--min-radius", type=float,
                   help="nm: compare loads whose Hertz radius is at least this (default 5 element sizes)")
    p.add_argument("--radius", choices=RADIUS_ESTIMATORS, default="pressure_fit",
                   help="FE contact radius compared: pressure_fit, edge, area (contact_radius_<this>) or plain "
                        "(contact_radius)")
    p.add_argument("--tip-radius", type=float, default=27.0, help="R of the tip, nm (default 27, the CI decks)")
    p.add_argument("--youngs-modulus", type=float, default=161.0, help="E of both bodies, GPa (default 161)")
    p.add_argument("--poissons-ratio", type=float, default=0.23, help="nu of both bodies (default 0.23)")
    p.add_argument("--plot", help="PNG to write")
    a = p.parse_args()
    R, ESTAR = a.tip_radius * 1e-9, effective_modulus(a.youngs_modulus * 1e9, a.poissons_ratio)
    rows = read_full_history(a.output)  # a quarter model's forces times 4 (its log.txt says which it is)
    h = a.element_size * 1e-9
    min_radius = (a.min_radius if a.min_radius is not None else 5 * a.element_size) * 1e-9
    column = radius_column(a.radius)
    hertz_radius = lambda P: dmt_radius(P, R, 0.0, ESTAR)  # noqa: E731  (DMT with W = 0)
    used = []
    peak = 0.0
    for r in rows:
        P = r["contact_normal_force"]
        if P < peak:  # loading branch only
            break
        peak = P
        if min_radius <= hertz_radius(P) <= 0.25 * R:
            used.append(r)
    if len(used) < 5:
        print(f"FAIL: only {len(used)} usable rows (need loads with a Hertz radius between {min_radius * 1e9:.2f} nm and R/4)")
        return 1
    P, aFE, aH, ea = radius_errors(used, column, hertz_radius)
    dH = [x * x / R for x in aH]
    dtot = [-r["tip_top_displacement_z"] - r["contact_max_penetration"] for r in used]
    C = sum((dt - dh) * x for dt, dh, x in zip(dtot, dH, P)) / sum(x * x for x in P)
    dFE = [dt - C * x for dt, x in zip(dtot, P)]
    ed = relative_errors(dFE, dH)
    ke = max_kinetic_over_stored(used)
    ok = max(ea) <= a.tolerance and max(ed) <= a.tolerance and ke < 0.02
    if model_fraction(a.output) != 1.0:
        print("quarter model (symmetry = quarter): forces, areas and energies times 4")
    print(f"E* = {ESTAR / 1e9:.2f} GPa, R = {R * 1e9:g} nm; {len(used)} loads from {P[0] * 1e9:.1f} to {P[-1] * 1e9:.1f} nN "
          f"(a from {aFE[0] * 1e9:.2f} to {aFE[-1] * 1e9:.2f} nm, a/R up to {aFE[-1] / R:.3f})")
    max_ea, mean_ea = max_and_mean(ea)
    print(f"contact radius ({column}, loads with a_H >= {min_radius * 1e9:.2f} nm = {min_radius / h:.1f} element sizes): "
          f"max error {max_ea:.2%} (mean {mean_ea:.2%}); tolerance {a.tolerance:.1%}")
    print_unchecked_radius(used, aH, a.radius)
    print(f"approach: far-field compliance C = {C * 1e9 * 1e-9:.4g} m/N ({C:.4g}); max error of delta - C P vs a^2/R "
          f"{max(ed):.2%}; tolerance {a.tolerance:.1%}")
    print(f"quasi-static: max kinetic/internal energy {ke:.2%} (limit 2 %)")
    print("PASS" if ok else "FAIL")
    if a.plot:
        plt = pyplot()
        allP = [r["contact_normal_force"] * 1e9 for r in rows if r["contact_normal_force"] > 0]
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
        Ps = [x * 1e9 for x in P]
        grid = [max(allP) * i / 200 for i in range(1, 201)]
        ax1.plot(grid, [hertz_radius(x * 1e-9) * 1e9 for x in grid], "k-", label="Hertz")
        ax1.plot(Ps, [r["contact_radius_pressure_fit"] * 1e9 for r in used], "o", ms=3,
                 label="FE, elliptic fit of the nodal pressures" + (" (checked)" if a.radius == "pressure_fit" else ""))
        ax1.plot(Ps, [r["contact_radius_edge"] * 1e9 for r in used], "^", ms=3,
                 label="FE, gap sign change on edges (= contact_radius)" + (" (checked)" if a.radius in ("edge", "plain") else ""))
        ax1.plot(Ps, [r["contact_radius_area"] * 1e9 for r in used], "x", ms=3,
                 label="FE sqrt(area/pi) (node rings)" + (" (checked)" if a.radius == "area" else ""))
        ax1.set_xlabel("contact force P (nN)")
        ax1.set_ylabel("contact radius a (nm)")
        ax1.legend(fontsize=8)
        ax2.plot(grid, [hertz_radius(x * 1e-9) ** 2 / R * 1e9 for x in grid], "k-", label="Hertz a^2/R")
        ax2.plot(Ps, [x * 1e9 for x in dFE], "o", ms=3, label="FE approach - C P")
        ax2.set_xlabel("contact force P (nN)")
        ax2.set_ylabel("approach (nm)")
        ax2.legend(fontsize=8)
        fig.suptitle(f"Hertz, R = {a.tip_radius:g} nm, E* = {ESTAR / 1e9:.1f} GPa, element {a.element_size} nm: "
                     f"max errors a ({column}) {max(ea):.1%}, delta {max(ed):.1%}")
        save_figure(fig, a.plot)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(guarded(main))
