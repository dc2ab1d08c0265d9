#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Plane P wave in a uniaxial-strain silicon column (inputs/examples/wave_bar.i) against 1-D theory.

Piston velocity v0 ramped over t_r = 1 ps at the top of a column of length L = 100 nm, area A = 1 nm^2.
Theory: c_d = sqrt((lambda + 2 mu)/rho) = 8854 m/s for E = 160 GPa, nu = 0.22, rho = 2330 kg/m^3;
the stress behind the front is rho c_d v0 (piston force rho c_d v0 A at the top) and doubles at the
fixed bottom (reaction 2 rho c_d v0 A), reached at half height at t = L/c_d + t_r/2.
Tolerances: arrival time within 1 % of L/c_d (wave speed within 1 %), plateaus within 2 %,
energy-balance error below 0.5 % (docs/theory.md 1.5 verification handle).
"""
import argparse
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import finish_axes, pyplot, read_history, save_figure  # noqa: E402
from cli_errors import guarded  # noqa: E402

E, NU, RHO = 160e9, 0.22, 2330.0
L, A, V0, T_RAMP = 100e-9, 1e-18, 1.0, 1e-12


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("history")
    p.add_argument("--plot")
    a = p.parse_args()
    rows = read_history(a.history)
    t = [r["time"] for r in rows]
    bottom = [r["bar_zmin_reaction_z"] for r in rows]
    top = [-r["bar_zmax_reaction_z"] for r in rows]  # force the piston applies, downward
    err = max(r["energy_error"] for r in rows)

    lam = E * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E / (2 * (1 + NU))
    c = math.sqrt((lam + 2 * mu) / RHO)
    transit = L / c
    piston = RHO * c * V0 * A
    # Arrival: first time the bottom reaction reaches half of its doubled plateau.
    i = next(k for k, r in enumerate(bottom) if r >= piston)
    t_arr = t[i - 1] + (piston - bottom[i - 1]) * (t[i] - t[i - 1]) / (bottom[i] - bottom[i - 1])
    expected_arr = transit + 0.5 * T_RAMP
    arr_err = abs(t_arr - expected_arr) / transit
    window = [r for tt, r in zip(t, bottom) if tt > t_arr + 3e-12]
    bottom_plateau = sum(window) / len(window)
    top_window = [r for tt, r in zip(t, top) if 3e-12 < tt < 2 * transit]
    top_plateau = sum(top_window) / len(top_window)
    bot_err = abs(bottom_plateau - 2 * piston) / (2 * piston)
    top_err = abs(top_plateau - piston) / piston
    ok = arr_err < 0.01 and bot_err < 0.02 and top_err < 0.02 and err < 0.005
    print(f"wave speed c_d = {c:.1f} m/s, transit L/c_d = {transit * 1e12:.3f} ps")
    print(f"arrival at the fixed end: {t_arr * 1e12:.3f} ps vs {expected_arr * 1e12:.3f} ps: "
          f"error {arr_err:.3%} of the transit time (tolerance 1 %)")
    print(f"piston force {top_plateau:.5e} N vs rho c v0 A = {piston:.5e} N: error {top_err:.3%} (tolerance 2 %)")
    print(f"fixed-end reaction {bottom_plateau:.5e} N vs 2 rho c v0 A = {2 * piston:.5e} N: "
          f"error {bot_err:.3%} (tolerance 2 %)")
    print(f"max energy-balance error {err:.2e} (tolerance 5e-3)")
    print("PASS" if ok else "FAIL")
    if a.plot:
        fig, ax = pyplot().subplots(figsize=(6, 4))
        ax.plot([x * 1e12 for x in t], [x * 1e12 for x in bottom], label="FE reaction at the fixed end")
        ax.plot([x * 1e12 for x in t], [x * 1e12 for x in top], label="FE piston force")
        ax.axhline(2 * piston * 1e12, ls="--", c="k", lw=0.8, label="2 rho c v0 A, rho c v0 A")
        ax.axhline(piston * 1e12, ls="--", c="k", lw=0.8)
        ax.axvline(expected_arr * 1e12, ls=":", c="r", lw=0.8, label="L/c_d + t_r/2")
        finish_axes(ax, "time (ps)", "force (pN)")
        save_figure(fig, a.plot)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(guarded(main))
