#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""The rough-surface law with the attraction of the non-contacting area (issue 26; docs/theory.md
10.6) on flats (noncontact.i): the FE run's apparent pressure at the mean-plane separation read back
from the run against the model evaluated directly and independently of the C++ tables (scipy quadrature
of the GW integrals and of the Lennard-Jones law over the Gaussian surface heights), within 0.5 % of
the larger of its two parts (asperity contacts, attraction: the net pressure crosses zero on the way);
the attraction alone where no asperity touches (d >= 6 sigma_s) within 0.5 %; |energy_error| below
1 % from 20 ns on.

usage: compare_noncontact.py HISTORY.csv [--plot OUT.png]
"""
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import finish_axes, history_parser, pyplot, read_history, report_failures, save_figure  # noqa: E402
from rough_theory import gw_integral, noncontact_attraction  # noqa: E402
from cli_errors import guarded  # noqa: E402

ETA, R, SIGMA = 3.796e16, 14.71e-9, 1.536e-9        # di-5 summits: 1/m^2, m, m
E_STAR, W = 84.1e9, 0.1                              # Pa, J/m^2
Z0, HC = 0.2e-9, 200 * 0.2e-9                        # the attraction's z0 and cut-off (default 200 z0), m
OFFSET = 10e-9                                       # mean plane offset, m
TOL = 0.005


def attraction(d):
    return noncontact_attraction(d, W, Z0, HC, SIGMA)


def contact(d):
    """Hertz part and DMT pull of the continuous GW model (Pa)."""
    t = d / SIGMA
    return (ETA * (4.0 / 3.0) * E_STAR * math.sqrt(R) * SIGMA ** 1.5 * gw_integral(1.5, t),
            ETA * 2.0 * math.pi * W * R * gw_integral(0.0, t))


def main():
    a = history_parser(__doc__, "PNG: apparent pressure against d, FE and the direct model").parse_args()
    rows = [r for r in read_history(a.history) if r["time"] > 0.0]
    failures, points = [], []
    for r in rows:
        d = OFFSET + r["upper_zmin_displacement_z"]
        hertz, dmt = contact(d)
        pull = attraction(d)
        model = hertz - dmt - pull
        points.append((d, r["apparent_pressure"], model, hertz, dmt + pull))
    worst = max(points, key=lambda p: abs(p[1] - p[2]) / max(p[3], p[4]))
    err = abs(worst[1] - worst[2]) / max(worst[3], worst[4])
    print(f"{len(points)} rows, d from {max(p[0] for p in points) * 1e9:.3f} to {min(p[0] for p in points) * 1e9:.3f} nm; "
          f"worst |p_FE - p_model| = {100 * err:.4f} % of the larger part at d = {worst[0] * 1e9:.3f} nm "
          f"(FE {worst[1]:.6g} Pa, model {worst[2]:.6g} Pa; tolerance 0.5 %)")
    if err > TOL:
        failures.append(f"apparent pressure differs from the direct model by {100 * err:.3f} % (> 0.5 %)")
    free = [p for p in points if p[0] >= 6 * SIGMA]
    if not free:
        failures.append("no row without asperity contact (d >= 6 sigma_s)")
    else:
        e = max(abs(p[1] + attraction(p[0])) / attraction(p[0]) for p in free)
        print(f"no asperity contact (d >= 6 sigma_s, {len(free)} rows): attraction {-free[0][1] / 1e3:.4g} kPa at "
              f"d = {free[0][0] * 1e9:.3f} nm ({-free[0][1] * 1e-3:.4g} nN/um^2); worst error {100 * e:.4f} % (0.5 %)")
        if e > TOL:
            failures.append(f"the attraction alone differs from the direct integral by {100 * e:.3f} % (> 0.5 %)")
    energy = max(abs(r["energy_error"]) for r in rows if r["time"] >= 20e-9)
    print(f"max |energy_error| from 20 ns on {energy:.3g} (tolerance 0.01)")
    if energy > 0.01:
        failures.append(f"energy error {energy:.3g} from 20 ns on (> 1 %)")
    if a.plot:
        fig, ax = pyplot().subplots(figsize=(5.5, 4))
        ax.plot([p[0] * 1e9 for p in points], [p[2] / 1e3 for p in points], "-", label="direct model: GW + DMT - attraction")
        ax.plot([p[0] * 1e9 for p in points], [p[1] / 1e3 for p in points], "o", ms=2.5, label="FE apparent pressure")
        ax.plot([p[0] * 1e9 for p in points], [(p[3] - p[4] + attraction(p[0])) / 1e3 for p in points], ":",
                label="without the attraction (Eq. 4.10)")
        ax.set_yscale("symlog", linthresh=10)
        finish_axes(ax, "mean-plane separation d (nm)", "apparent pressure (kPa)", "di-5 flats, W = 0.1 J/m^2")
        save_figure(fig, a.plot)
    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(guarded(main))
