#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""First yield under a Hertz contact (hertz_yield.i; docs/theory.md 3.3, 8.1): two identical J2 bodies
(E 161 GPa, nu 0.23, Y 4 GPa), sphere R = 27 nm on a flat. On the axis of the Hertz field (Johnson,
Contact Mechanics, 1985, eq. 3.45) sigma_z/p0 = -1/(1 + z^2/a^2) and sigma_r/p0 = -(1 + nu)(1 -
(z/a) atan(a/z)) + 1/(2 (1 + z^2/a^2)); the von Mises stress |sigma_r - sigma_z| peaks at z_y/a
below the surface, so first yield comes at p0 = c(nu) Y (computed here: c = 1.532, z_y = 0.458 a for
nu = 0.23; 1.61 and 0.48 for nu = 0.3).

Checks: (1) the Hertz peak pressure p0 = (6 P E*^2 / (pi^3 R^2))^(1/3) at the contact force P of the
first history row with plastic dissipation, and of the row before it, within 3 % of c Y; (2) the
element that has yielded most at the first field output with any plastic strain lies, by its centroid,
within half an element size of the depth z_y (a = pi p0 R / (2 E*) at c Y) below the reference surface
of its body (the 0.8 nm mesh resolves the depth no finer). On a quarter model (symmetry = quarter, read
from the run's log.txt) P is the history's force times 4; the element on the axis is one of the quarter's.

usage: compare_hertz_yield.py OUTPUT [--element-size 0.8] [--plot OUT.png]
"""
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import (finish_axes, history_parser, pyplot, read_full_history, report_failures,  # noqa: E402
                            save_figure)
from results_h5 import si  # noqa: E402
from cli_errors import guarded  # noqa: E402

E, NU, Y, R = 161e9, 0.23, 4e9, 27e-9   # the deck's silicon and sphere
E_STAR = E / (2 * (1 - NU * NU))        # two identical bodies


def first_yield_on_axis(nu):
    """(c, z_y/a): the largest von Mises stress on the axis of the Hertz field over p0, inverted."""
    best, depth = 0.0, 0.0
    for i in range(1, 30001):
        z = i / 10000.0
        sz = -1.0 / (1.0 + z * z)
        sr = -(1.0 + nu) * (1.0 - z * math.atan(1.0 / z)) + 0.5 / (1.0 + z * z)
        if abs(sr - sz) > best:
            best, depth = abs(sr - sz), z
    return 1.0 / best, depth


def hertz_p0(force):
    return (6.0 * force * E_STAR ** 2 / (math.pi ** 3 * R ** 2)) ** (1.0 / 3.0)


def main():
    ap = history_parser(__doc__, "PNG: plastic dissipation against p0/Y, with c(nu)", "output")
    ap.add_argument("--element-size", type=float, default=0.8, help="element size at the contact, nm")
    a = ap.parse_args()
    c, z_over_a = first_yield_on_axis(NU)
    a_y = math.pi * c * Y * R / (2.0 * E_STAR)
    print(f"theory (nu = {NU}): first yield at p0 = {c:.4f} Y = {c * Y / 1e9:.4f} GPa, depth {z_over_a:.3f} a = "
          f"{z_over_a * a_y * 1e9:.3f} nm (a = {a_y * 1e9:.3f} nm)")
    failures = []

    rows = read_full_history(a.output)  # a quarter model's force times 4 (its log.txt says which it is)
    first = next((i for i, r in enumerate(rows) if r["plastic_dissipation"] > 0.0), None)
    if first is None or first == 0:
        return report_failures(["no row with plastic dissipation (or plastic from the start)"], verdict=True)
    for label, r in (("last elastic row", rows[first - 1]), ("first plastic row", rows[first])):
        p0 = hertz_p0(r["contact_normal_force"])
        err = p0 / (c * Y) - 1
        print(f"{label}: t {r['time'] * 1e12:.1f} ps, P {r['contact_normal_force'] * 1e9:.2f} nN, "
              f"p0 {p0 / 1e9:.4f} GPa = {p0 / Y:.4f} Y: {100 * err:+.2f} % against c Y (tolerance 3 %)")
        if abs(err) > 0.03:
            failures.append(f"{label}: p0 {p0 / Y:.4f} Y differs from {c:.4f} Y by {100 * err:.2f} % (> 3 %)")

    import h5py
    import numpy as np
    with h5py.File(pathlib.Path(a.output) / "results.h5") as f:
        x = si(f["mesh/coordinates"])  # m, whatever the file's length unit
        conn = f["mesh/connectivity"][()]
        block = f["mesh/block_id"][()]
        step = next((s for s in sorted(f["steps"].keys())
                     if f["steps"][s]["element/equivalent_plastic_strain"][()].max() > 0), None)
        if step is None:
            failures.append("no field output with plastic strain")
        else:
            eqps = f["steps"][step]["element/equivalent_plastic_strain"][()]
            time = f["steps"][step].attrs["time"]
            e = int(eqps.argmax())
            centroid = x[conn[e]].mean(axis=0)
            body = np.unique(conn[block == block[e]])
            # The substrate lies below its top face, the tip above its apex (reference coordinates):
            # the depth from the nearer of the body's extreme planes.
            z_body = x[body, 2]
            depth = min(z_body.max() - centroid[2], centroid[2] - z_body.min())
            miss = abs(depth - z_over_a * a_y)
            print(f"first field output with plastic strain: t {time * 1e12:.1f} ps, {int((eqps > 0).sum())} element(s) "
                  f"yielded; the largest ({eqps[e]:.3g}) is element {e + 1} of block {int(block[e])}, centroid "
                  f"{depth * 1e9:.3f} nm below the surface vs {z_over_a * a_y * 1e9:.3f} nm: off by {miss * 1e9:.3f} nm "
                  f"(tolerance half an element, {0.5 * a.element_size:.2f} nm)")
            if miss > 0.5 * a.element_size * 1e-9 * (1 + 1e-9):
                failures.append(f"first yield {depth * 1e9:.3f} nm deep, theory {z_over_a * a_y * 1e9:.3f} nm")

    if a.plot:
        plt = pyplot()
        fig, ax = plt.subplots(figsize=(5.5, 4))
        plastic = [r for r in rows if r["plastic_dissipation"] > 0]
        ax.semilogy([hertz_p0(r["contact_normal_force"]) / Y for r in plastic],
                    [r["plastic_dissipation"] * 1e21 for r in plastic], label="FE plastic dissipation (log scale)")
        ax.axvline(c, color="k", ls="--", lw=1, label=f"first yield, Hertz + von Mises: p0 = {c:.3f} Y")
        ax.set_xlim(1.4, max(hertz_p0(r["contact_normal_force"]) for r in rows) / Y)
        finish_axes(ax, "Hertz peak pressure of the FE contact force, p0 / Y", "plastic dissipation (zJ)",
                    "Si sphere on Si flat, J2: Y = 4 GPa, R = 27 nm")
        save_figure(fig, a.plot)
    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(guarded(main))
