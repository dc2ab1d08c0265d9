#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The FE's contact pressure against the layered continuum's p(r) at the same load (issue 52, cases 4 and 5):
separates what the contact radius estimator reads from what the contact itself does.

  /usr/bin/python3 verification/coated/pressure_profile.py RUN [RUN ...] [--runs build/verification] [--tribex BIN] [--rows]

RUN: a deck of make_decks.RUNS with field output (the diag_* decks). At every field output on diagnose.py's
rows (P~ from 0.02 to the case's maximum, a from 3 element sizes to the fine region's edge), with the
continuum's pressure p_ref(r) at the row's own P~ (`tribex layered --pressure`), its radius a_ref and its
approach delta_ref:

  overlap    the penalty's interpenetration at the axis (-gap of the slave node on the axis) over delta_ref;
  edge       contact_radius_edge (the study's estimator) over a_ref, as (a/a_ref)^2 - 1 (= f_FE/f_ref - 1);
  shape      the radius of the continuum's own profile fitted to the FE's slave nodal forces: F_I =
             lambda int p_ref(r a_ref/a) N_I dA, lambda and a by least squares (it reads the forces, not the
             gap, so not the penalty's overlap; and the profile is the continuum's, so no shape is assumed);
  cfit_ref   diagnose.py's consistent fit (sqrt(1 - r^2/a^2)(c0 + c1 r^2/a^2)) applied to the continuum's
             own consistent nodal forces on the same mesh: that estimator's bias where the answer is a_ref;
  cfit       the same fit to the FE's nodal forces;
  force      the FE's nodal forces against the continuum's consistent ones, sum |F_FE - F_ref| / sum F_ref.

Printed per run: the means over the P~ bins 0.02-0.05, 0.05-0.2, 0.2-0.8, > 0.8 and the exponent difference
b_FE - b_ref that each radius gives over the same rows (as diagnose.py); --rows prints every row.
"""
import argparse
import math
import os
import sys
import tempfile

import numpy as np

from diagnose import ROOT, consistent_fit, edge_crossings, in_study_range, loading_outputs, run_layered
from compare_reference import BINS  # noqa: E402
from make_decks import RUNS  # noqa: E402

RADII = 400  # continuum pressure samples per load (uniform in r/a; p/sqrt(1 - (r/a)^2) is smooth, interpolated)


def continuum_profiles(name, tribex, p_tilde):
    """Per load: (a_ref m, delta_ref m, x = r/a samples, q = p/sqrt(1 - x^2) in Pa) from `tribex layered`."""
    with tempfile.TemporaryDirectory() as tmp:
        run_layered(name, tribex, p_tilde, tmp, ("--pressure", str(RADII)))
        curve, prof = (np.array([[float(v) for v in ln.split(",")] for ln in open(os.path.join(tmp, fn))
                                 if ln[0] not in "#p"]) for fn in ("layered.csv", "pressure.csv"))
    out = []
    for k in range(len(p_tilde)):
        block = prof[k * RADII:(k + 1) * RADII]
        x = block[:, 2]
        out.append((curve[k, 2] * 1e-9, curve[k, 3] * 1e-9, x, block[:, 3] * 1e9 / np.sqrt(1 - x * x)))
    return out


def profile_forces(fi, x, q, a):
    """Consistent nodal forces int p N_I dA of p(r) = q(r/a) sqrt(1 - r^2/a^2)_+ on the faces at fi's positions."""
    s = np.sqrt(fi.rho2) / a
    p = np.where(s < 1, np.interp(np.minimum(s, x[-1]), x, q) * np.sqrt(np.clip(1 - s * s, 0, None)), 0.0)
    return fi.nodal(p * fi.dA)


def shape_fit(fi, force, x, q, a_ref):
    """Radius a (and amplitude) of the continuum's profile q(r/a) that best fits the nodal forces (golden section)."""
    def residual(a):
        m = profile_forces(fi, x, q, a)
        lam = (m @ force) / (m @ m)
        return ((force - lam * m) ** 2).sum()
    lo, hi = 0.8 * a_ref, 1.25 * a_ref
    for _ in range(40):
        m1, m2 = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
        lo, hi = (lo, m2) if residual(m1) < residual(m2) else (m1, hi)
    return 0.5 * (lo + hi)


def field_rows(name, folder):
    """(time, P, edge, positions, gap, nodal forces) at every field output of the loading branch, and the faces."""
    outputs, fi = loading_outputs(folder)
    rows = []
    for o in outputs:
        X, g = o["X"], o["g"]
        axis = int(np.argmin(np.where(o["slave"], X[:, 0] ** 2 + X[:, 1] ** 2, np.inf)))
        rows.append(dict(time=o["time"], P=o["P"], delta=o["delta"], edge=float(o["hist"]["contact_radius_edge"]),
                         edge_X=edge_crossings(fi.faces, g, X), x=o["x"], X=X, overlap=-float(g[axis]),
                         force=o["force"]))
    return rows, fi


def analyse(name, runs, tribex, show_rows):
    """One run: (per-row dicts of the measures, printed lines)."""
    rows, fi = field_rows(name, os.path.join(runs, "coated_" + name))
    rows, pn = in_study_range(name, rows)
    out = []
    for r, pt, (a_ref, d_ref, x, q) in zip(rows, pn, continuum_profiles(name, tribex, pn)):
        fi.at(r["x"])
        fi.at(r["X"])
        shape_X = shape_fit(fi, r["force"], x, q, a_ref)
        fi.at(r["x"])
        f_ref = profile_forces(fi, x, q, a_ref)
        reach = math.sqrt((r["x"][fi.nodes, :2] ** 2).sum(axis=1)[r["force"] > 0].max())
        out.append(dict(p_tilde=pt, a_ref=a_ref, overlap=r["overlap"] / d_ref, edge=(r["edge"] / a_ref) ** 2 - 1,
                        edge_X=(r["edge_X"] / a_ref) ** 2 - 1, shape_X=(shape_X / a_ref) ** 2 - 1,
                        shape=(shape_fit(fi, r["force"], x, q, a_ref) / a_ref) ** 2 - 1,
                        cfit_ref=(consistent_fit(fi, f_ref, a_ref) / a_ref) ** 2 - 1,
                        cfit=(consistent_fit(fi, r["force"], reach) / a_ref) ** 2 - 1,
                        force=np.abs(r["force"] - f_ref).sum() / f_ref.sum(), load=4 * f_ref.sum() / r["P"] - 1))
    return out, summary_lines(name, out, show_rows)


MEASURES = ("overlap", "edge", "edge_X", "shape", "shape_X", "cfit_ref", "cfit", "force", "load")


def summary_lines(name, out, show_rows):
    pn = np.array([o["p_tilde"] for o in out])
    lines = [f"{name} ({RUNS[name]['h']:g} nm; {len(out)} rows, P~ {pn.min():.3f}-{pn.max():.3f}): bins P~ 0.02-0.05, "
             "0.05-0.2, 0.2-0.8, > 0.8 (%); b_FE - b_ref for the radii"]
    for k in MEASURES:
        v = np.array([o[k] for o in out])
        bins = [v[(pn >= lo) & (pn < hi)].mean() if ((pn >= lo) & (pn < hi)).any() else float("nan") for lo, hi in BINS]
        tail = f"   b_FE - b_ref {np.polyfit(np.log(pn), np.log1p(v), 1)[0]:+.4f}" if k in ("edge", "edge_X", "shape", "shape_X", "cfit_ref", "cfit") else ""
        lines.append(f"  {k:9s} " + " ".join(f"{100 * b:+7.3f}" for b in bins) + tail)
    if show_rows:
        lines += ["    P~ {:.4f} a_ref {:.3f} nm ".format(o["p_tilde"], o["a_ref"] * 1e9)
                  + " ".join(f"{k} {100 * o[k]:+6.2f}" for k in MEASURES) for o in out]
    return lines


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", nargs="+", help="deck names (make_decks.RUNS) of runs with field output, e.g. diag_case4_h0.2")
    ap.add_argument("--runs", default=str(ROOT / "build" / "verification"), help="folder of the coated_<run> folders")
    ap.add_argument("--tribex", default=str(ROOT / "build" / "bin" / "tribex"), help="the tribex binary")
    ap.add_argument("--rows", action="store_true", help="print every row")
    a = ap.parse_args()
    for name in a.run:
        if name not in RUNS:
            print(f"pressure_profile.py: error: unknown run '{name}' (make_decks.py RUNS)", file=sys.stderr)
            return 2
        _, lines = analyse(name, a.runs, a.tribex, a.rows)
        print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
