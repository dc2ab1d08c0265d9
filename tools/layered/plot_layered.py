#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Plot of `tribex layered`: f against P~ (log axis) with the fitted power law, and the contact radius
against the load. Run by the tool with /usr/bin/python3 (matplotlib):

  plot_layered.py DIR/layered.csv --out DIR/layered.png [--A A --b b --fit LO,HI] [--title TEXT]
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    rows = [r for r in csv.reader(line for line in open(path) if not line.startswith("#"))]
    head = rows[0]
    return {h.split("[")[0]: [float(r[i]) for r in rows[1:]] for i, h in enumerate(head)}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("--out", required=True)
    ap.add_argument("--A", type=float)
    ap.add_argument("--b", type=float)
    ap.add_argument("--fit")
    ap.add_argument("--title", default="")
    a = ap.parse_args()
    d = read(a.csv)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 3.8))
    ax1.plot(d["p_tilde"], d["f"], ".", ms=4, label="layered continuum (tribex layered)")
    if a.A is not None and a.fit:
        lo, hi = (float(v) for v in a.fit.split(","))
        g = [lo * (hi / lo) ** (i / 100) for i in range(101)]
        ax1.plot(g, [a.A * x ** a.b for x in g], "k-", lw=1, label=f"fit A P~^b: A = {a.A:.4f}, b = {a.b:.4f}")
    ax1.set_xscale("log")
    ax1.set_xlabel("P~ = P / (E*_top h_top^2)  (-)")
    ax1.set_ylabel("f = a^2 / (3PR/(4E_eff))^(2/3)  (-)")
    ax1.legend(fontsize=8)
    ax2.plot(d["load"], d["contact_radius"], "-", label="contact radius a")
    ax2.set_xlabel("load P (nN)")
    ax2.set_ylabel("contact radius a (nm)")
    ax2.legend(fontsize=8)
    fig.suptitle(a.title, fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)


if __name__ == "__main__":
    main()
