#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""PNG plots of the report's Figs. 4.6, 4.7, 4.8, 4.10 and 4.11 (nondimensional GW) from the CSVs of
`tribex gw figures --out DIR` and `tribex surface contact FILE --csv DIR/fig4_10.csv`.

usage: /usr/bin/python3 tools/plot/gw_figures.py DIR     (writes DIR/fig4_*.png)
"""
import os
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from history_checks import pyplot  # noqa: E402  (matplotlib, Agg: imported after the inputs are checked)
from cli_errors import guarded, read_csv_rows, require_folder  # noqa: E402


def rows(path):
    return read_csv_rows(path, "a CSV of tribex gw figures", "run `tribex gw figures --out DIR` first")


def main(d):
    require_folder(d, "the --out folder of tribex gw figures")
    # Fig. 4.6: discrete populations converge to the continuous curve.
    r = rows(os.path.join(d, "fig4_6.csv"))
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    for label in sorted({x["contacting_at_t1.5"] for x in r}, key=lambda s: float(s)):
        sel = [x for x in r if x["contacting_at_t1.5"] == label and float(x["load"]) > 0]
        name = "continuous" if label == "inf" else f"{float(label):g} contacting at d/σs = 1.5"
        ax.loglog([float(x["load"]) for x in sel], [float(x["area"]) for x in sel], "-" if label == "inf" else ".-",
                  ms=2, lw=2 if label == "inf" else 1, label=name)
    ax.set_xlabel(r"load $P / (\frac{4}{3} E^* \sqrt{R}\, \sigma_s^{3/2} N)$")
    ax.set_ylabel(r"real area $A / (\pi R \sigma_s N)$")
    ax.set_title("Fig. 4.6: discrete GW populations vs continuous")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "fig4_6.png"), dpi=130)

    # Figs. 4.7 and 4.8: Hertz vs DMT GW.
    r = rows(os.path.join(d, "fig4_7_8.csv"))
    beta = float(r[0]["beta"])
    area = [float(x["area"]) for x in r]
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    ax.plot([float(x["hertz_load"]) for x in r], area, "-", label="GW, Hertz")
    ax.plot([float(x["dmt_load"]) for x in r], area, "--", label=f"GW, DMT (β = {beta:g})")
    ax.axvline(0, color="0.7", lw=0.8)
    ax.set_xlim(-beta * 0.6, 0.3)
    ax.set_ylim(0, 0.3)
    ax.set_xlabel(r"applied load $P / (\frac{4}{3} E^* \sqrt{R}\, \sigma_s^{3/2} N)$")
    ax.set_ylabel(r"real area $A / (\pi R \sigma_s N)$")
    ax.set_title("Fig. 4.7: contact area vs normal load")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(d, "fig4_7.png"), dpi=130)

    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    for key, style, name in (("hertz_load", "-", "GW, Hertz"), ("dmt_load", "--", f"GW, DMT (β = {beta:g})")):
        sel = [x for x in r if float(x[key]) > 1e-4]
        ax.semilogy([float(x[key]) for x in sel], [float(x["area"]) / float(x[key]) for x in sel], style, label=name)
    ax.set_xlim(0, 0.3)
    ax.set_xlabel(r"applied load $P / (\frac{4}{3} E^* \sqrt{R}\, \sigma_s^{3/2} N)$")
    ax.set_ylabel("area / load (nondimensional)")
    ax.set_title("Fig. 4.8: area/load vs load (unbounded for DMT)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(d, "fig4_8.png"), dpi=130)

    # Fig. 4.10: discrete GW on an AFM map's own summits, Hertz vs DMT.
    p = os.path.join(d, "fig4_10.csv")
    if os.path.exists(p):
        r = [x for x in rows(p) if int(x["contacts"]) > 0]
        fig, axes = plt.subplots(1, 2, figsize=(9.5, 4.2))
        af = [float(x["area_fraction"]) for x in r]
        ph = [float(x["pressure_hertz_Pa"]) / 1e6 for x in r]
        pd = [float(x["pressure_dmt_Pa"]) / 1e6 for x in r]
        low = -min(pd) if min(pd) < 0 else 0.01 * max(ph)
        for ax, xmax, title in ((axes[0], 0.3 * max(ph), "full range"), (axes[1], 8 * low, "first contacts")):
            ax.plot(ph, af, "-", label="Hertz")
            ax.plot(pd, af, "--", label="DMT, W = 0.1 J/m²")
            ax.axvline(0, color="0.7", lw=0.8)
            ax.set_xlim(-1.5 * low, xmax)
            ax.set_ylim(0, max([a for a, p in zip(af, ph) if p <= xmax] + [1e-9]) * 1.1)
            ax.set_xlabel("applied pressure over the map area (MPa)")
            ax.set_ylabel("real area / map area")
            ax.set_title(title, fontsize=9)
            ax.legend(fontsize=8)
        fig.suptitle("Fig. 4.10: discrete GW on the AFM map's summits (di-3, 10 x 10 µm²)")
        fig.tight_layout()
        fig.savefig(os.path.join(d, "fig4_10.png"), dpi=130)

    # Fig. 4.11: tangential force vs slip, continuous and discrete.
    r = rows(os.path.join(d, "fig4_11.csv"))
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    s = [float(x["slip"]) for x in r]
    ax.plot(s, [float(x["continuous"]) for x in r], "-", label="continuous distribution")
    ax.plot(s, [float(x["discrete"]) for x in r], "--", label="discrete, ~100 contacting asperities")
    ax.set_xlabel(r"slip $\delta / (\pi \tau^* \sqrt{R \sigma_s} / 8 G^*)$")
    ax.set_ylabel(r"tangential force / $(\tau^* A)$")
    ax.set_title("Fig. 4.11: tangential force vs slip (d/σs = 1)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(d, "fig4_11.png"), dpi=130)
    print("wrote", ", ".join(sorted(f for f in os.listdir(d) if f.endswith(".png"))))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    sys.exit(guarded(lambda: main(sys.argv[1])))
