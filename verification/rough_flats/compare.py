#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Rough-surface (GW) contact on flats (issue 10 acceptance): the FE run's apparent pressure and real
contact area against the GW integrals evaluated directly (scipy quadrature, independent of the C++
table) at the mean-plane separation read back from the run, within 0.5 %; in steady sliding the
friction force equals tau* x real area (tanh(V/v_ref) = 1 at V = 10 v_ref) within 0.5 %; kinetic energy
below 2 % of internal energy in the hold (quasi-static check: during the press and the slide the block
translates rigidly at 1.4 and 5 m/s, and that kinetic energy is the drive, not a dynamic error).

usage: compare.py HISTORY.csv [--plot OUT.png]
"""
import math
import pathlib
import sys

from scipy import integrate

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from cli_errors import guarded  # noqa: E402
from history_checks import (finish_axes, history_parser, max_kinetic_over_stored, mean, pyplot,  # noqa: E402
                            read_history, report_failures, rows_between, save_figure)

# The deck's parameters (rough_flats.i)
ETA, R, SIGMA = 26.14e12, 192.9e-9, 35.01e-9       # 1/m^2, m, m
E_STAR, W, TAU = 84.1e9, 0.05, 100e6                # Pa, J/m^2, Pa
OFFSET = 200e-9                                     # mean plane offset, m
A0 = 2e-6 * 2e-6                                    # nominal area of the upper block's face, m^2
PRESS = (20e-9, 150e-9)                              # s, pressing and hold (before the slide)
HOLD = (110e-9, 150e-9)                              # s, load held (kinetic energy check)
SLIDE = (170e-9, 200e-9)                             # s, steady sliding at 5 m/s (starts at 150 ns)
TOL = 0.005


def gw_f(n, t):
    """F_n(t) = (1/sqrt(2 pi)) int_t^inf (s - t)^n exp(-s^2/2) ds (report Eq. 4.9)."""
    value, _ = integrate.quad(lambda s: (s - t) ** n * math.exp(-0.5 * s * s), t, t + 40.0, epsabs=0, epsrel=1e-12, limit=200)
    return value / math.sqrt(2.0 * math.pi)


def gw(d):
    """Apparent pressure (Pa) and real-area fraction of the continuous GW model with DMT per asperity."""
    t = d / SIGMA
    hertz = ETA * (4.0 / 3.0) * E_STAR * math.sqrt(R) * SIGMA ** 1.5 * gw_f(1.5, t)
    adhesion = ETA * 2.0 * math.pi * W * R * gw_f(0.0, t)
    return hertz - adhesion, math.pi * ETA * R * SIGMA * gw_f(1.0, t)


def main():
    ap = history_parser(__doc__, "PNG: apparent pressure against d (FE and GW), friction against time")
    a = ap.parse_args()
    rows = read_history(a.history)
    failures = []
    press = [r for r in rows if PRESS[0] <= r["time"] <= PRESS[1] and r["apparent_pressure"] > 1e3]
    if not press:
        failures.append("no pressing rows with an apparent pressure above 1 kPa")
    worst_p = worst_a = 0.0
    points = []
    for r in press:
        d = OFFSET + r["upper_zmin_displacement_z"]
        p_gw, frac_gw = gw(d)
        p_fe, area_fe = r["apparent_pressure"], r["real_contact_area"]
        worst_p = max(worst_p, abs(p_fe / p_gw - 1))
        worst_a = max(worst_a, abs(area_fe / (frac_gw * A0) - 1))
        points.append((d, p_fe, p_gw))
    worst_ke = max_kinetic_over_stored(rows_between(press, *HOLD), default=0.0)
    if press:
        dmin = min(p[0] for p in points)
        print(f"press: {len(press)} rows, d from {max(p[0] for p in points) * 1e9:.1f} to {dmin * 1e9:.1f} nm "
              f"(t = {dmin / SIGMA:.2f}), apparent pressure up to {max(p[1] for p in points) / 1e6:.4g} MPa")
        print(f"press: worst |p_FE / p_GW - 1| = {100 * worst_p:.4f} %, worst |A_FE / A_GW - 1| = {100 * worst_a:.4f} % "
              f"(tolerance {100 * TOL:.1f} %); max kinetic/internal energy in the hold {100 * worst_ke:.2e} % (2 %)")
        for what, worst in (("apparent pressure", worst_p), ("real contact area", worst_a)):
            if worst > TOL:
                failures.append(f"{what} differs from the direct GW integral by {100 * worst:.3f} % (> 0.5 %)")
        if worst_ke > 0.02:
            failures.append(f"kinetic energy reaches {100 * worst_ke:.2f} % of internal energy (> 2 %): not quasi-static")
    slide = rows_between(rows, *SLIDE)
    if not slide:
        failures.append("no rows in the sliding window")
    else:
        worst_f = 0.0
        for r in slide:
            d = OFFSET + r["upper_zmin_displacement_z"]
            _, frac_gw = gw(d)
            worst_f = max(worst_f, abs(r["friction_force"] / (TAU * frac_gw * A0) - 1))
        mean_f = mean(slide, "friction_force")
        print(f"slide: {len(slide)} rows, mean friction {mean_f:.5g} N; worst |F / (tau* A_c,GW) - 1| = {100 * worst_f:.4f} % "
              f"(tolerance {100 * TOL:.1f} %)")
        if worst_f > TOL:
            failures.append(f"friction differs from tau* x the GW real area by {100 * worst_f:.3f} % (> 0.5 %)")
    if a.plot:
        plt = pyplot()
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.8))
        ds = [OFFSET * 0.25 + i * (OFFSET * 0.8) / 120 for i in range(121)]
        ax1.semilogy([d * 1e9 for d in ds], [max(gw(d)[0], 1e-3) / 1e6 for d in ds], "-", label="GW integral (direct)")
        ax1.semilogy([p[0] * 1e9 for p in points], [p[1] / 1e6 for p in points], "o", ms=3, label="FE apparent pressure")
        finish_axes(ax1, "mean-plane separation d (nm)", "apparent pressure (MPa)")
        t = [r["time"] * 1e9 for r in rows]
        ax2.plot(t, [r["friction_force"] * 1e6 for r in rows], label="friction force (FE)")
        ax2.plot(t, [TAU * r["real_contact_area"] * 1e6 for r in rows], "--", label="tau* x real area")
        finish_axes(ax2, "time (ns): press 0-100, hold, slide 150-200", "force (µN)")
        save_figure(fig, a.plot, announce=None)
    return report_failures(failures)


if __name__ == "__main__":
    sys.exit(guarded(main))
