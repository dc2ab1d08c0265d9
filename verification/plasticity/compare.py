#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""J2 plasticity with linear isotropic hardening through the solver (docs/theory.md 3.3): the stress
against the strain of a 10 nm cube under uniaxial stress (uniaxial.i) or simple shear (shear.i), from
the reaction and the mean displacement of the driven face, against the closed form of the same
strain path (loading, then elastic unloading); the plastic dissipation at the end against
V (Y alpha + K alpha^2 / 2); the energy balance with the dissipation in it.

Tolerances: stress within 1 % of the yield stress on every row outside the two start-up transients
(0-20 ps and 200-220 ps, where the drive's velocity jumps and the mass damping has not yet calmed the
ringing); dissipation within 1 %; |energy_error| at most 1e-4 from 50 ps on (the elastic twin of the
uniaxial deck ends at 5e-6).

usage: compare.py OUTPUT --path uniaxial|shear [--plot OUT.png]
"""
import argparse
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import pyplot, read_history, report_failures, save_figure  # noqa: E402
from cli_errors import guarded  # noqa: E402

E, NU, Y, K = 161e9, 0.23, 4e9, 20e9   # Pa: the decks' material
L = 10e-9                               # m, cube edge
AREA, VOLUME = L * L, L ** 3
TRANSIENTS = ((0.0, 20e-12), (200e-12, 220e-12))  # s


def closed_form(path, strains):
    """Stress along the strain history by the 1-D bilinear law with unloading (exact for a straight
    path): uniaxial sigma(eps) with modulus E, yield Y, plastic modulus K; simple shear tau(gamma) with
    modulus mu, yield Y/sqrt(3), plastic modulus K/3. Returns the stresses and the final alpha."""
    if path == "uniaxial":
        modulus, yield0, hardening, alpha_per_plastic = E, Y, K, 1.0
    else:
        modulus, yield0, hardening, alpha_per_plastic = E / (2 * (1 + NU)), Y / math.sqrt(3), K / 3, 1 / math.sqrt(3)
    plastic, accumulated, out = 0.0, 0.0, []
    for s in strains:
        trial = modulus * (s - plastic)
        f = abs(trial) - (yield0 + hardening * accumulated)
        if f > 0:
            d = f / (modulus + hardening)
            plastic += math.copysign(d, trial)
            accumulated += d
            trial = modulus * (s - plastic)
        out.append(trial)
    return out, accumulated * alpha_per_plastic


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output")
    ap.add_argument("--path", choices=("uniaxial", "shear"), required=True)
    ap.add_argument("--plot", help="PNG: stress against strain, FE and closed form")
    a = ap.parse_args()
    rows = read_history(a.output)
    face = "cube_xmax" if a.path == "uniaxial" else "cube_zmax"
    strain = [r[f"{face}_displacement_x"] / L for r in rows]
    stress = [r[f"{face}_reaction_x"] / AREA for r in rows]
    expected, alpha = closed_form(a.path, strain)
    yield0 = Y if a.path == "uniaxial" else Y / math.sqrt(3)

    failures = []
    checked = [i for i, r in enumerate(rows) if not any(lo <= r["time"] <= hi for lo, hi in TRANSIENTS)]
    worst = max(checked, key=lambda i: abs(stress[i] - expected[i]))
    err = abs(stress[worst] - expected[worst]) / yield0
    print(f"{a.path}: {len(checked)} rows; worst |stress - closed form| = {100 * err:.3f} % of the yield stress "
          f"(strain {strain[worst]:.5f}, FE {stress[worst] / 1e9:.5f} GPa, closed form {expected[worst] / 1e9:.5f} GPa; "
          "tolerance 1 %)")
    if err > 0.01:
        failures.append(f"stress differs from the closed form by {100 * err:.2f} % of the yield stress (> 1 %)")

    dissipation = rows[-1]["plastic_dissipation"]
    reference = VOLUME * (Y * alpha + 0.5 * K * alpha * alpha)
    derr = dissipation / reference - 1
    print(f"plastic dissipation {dissipation:.6g} J vs V (Y alpha + K alpha^2/2) = {reference:.6g} J "
          f"(alpha {alpha:.6f}): {100 * derr:+.3f} % (tolerance 1 %)")
    if abs(derr) > 0.01:
        failures.append(f"plastic dissipation differs by {100 * derr:.2f} % (> 1 %)")

    late = [abs(r["energy_error"]) for r in rows if r["time"] >= 50e-12]
    print(f"max |energy_error| from 50 ps on: {max(late):.3g} (tolerance 1e-4); at the end {abs(rows[-1]['energy_error']):.3g}")
    if max(late) > 1e-4:
        failures.append(f"energy error {max(late):.3g} from 50 ps on (> 1e-4)")

    if a.plot:
        plt = pyplot()
        fig, ax = plt.subplots(figsize=(5.5, 4))
        label = "uniaxial stress sigma_xx" if a.path == "uniaxial" else "shear stress tau_xz"
        ax.plot([100 * s for s in strain], [s / 1e9 for s in stress], "o", ms=2.5, label=f"FE {label}")
        ax.plot([100 * s for s in strain], [s / 1e9 for s in expected], "-", lw=1, label="closed form (bilinear)")
        ax.set_xlabel("strain eps_xx (%)" if a.path == "uniaxial" else "shear strain gamma_xz (%)")
        ax.set_ylabel("stress (GPa)")
        ax.set_title(f"J2, Y = {Y / 1e9:g} GPa, K = {K / 1e9:g} GPa: {a.path}")
        ax.legend(fontsize=8)
        save_figure(fig, a.plot)
    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(guarded(main))
