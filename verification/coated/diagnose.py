#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""What tilts the FE's f (issue 52, scope 2): the contact radius of a coated-study run measured three
ways from its fields, and its load-approach curve, each against the layered continuum at the same load.

  /usr/bin/python3 verification/coated/diagnose.py RUN [RUN ...] [--runs build/verification] [--tribex BIN]
        [--csv OUT.csv] [--rows]

RUN is a deck name of make_decks.RUNS whose folder coated_RUN holds results.h5 with the fields
displacement, gap, contact_traction every few ps (the diag_* decks). For every field output with
P~ = P/(Ebar_c h_c^2) from 0.02 to the case's maximum and 3 to 11.5 element sizes of contact radius
(study.py's fitted rows, up to the fine region's edge), f_FE/f_ref - 1 = (a_FE/a_ref)^2 - 1 for:

  edge      contact_radius_edge of history.csv (the study's estimator: the gap's sign change on the
            slave-face edges, interpolated linearly between the edge's nodes, current positions);
  edge_X    the same crossings located at the nodes' reference positions X (u = x - X removed):
            the coating's surface flows outward under the sphere, which a small-strain continuum ignores;
  cfit      the radius of a smooth-edge pressure p = sqrt(1 - r^2/a^2)_+ (c0 + c1 r^2/a^2) fitted to
            the slave nodal forces through consistent loads, f_I = int p N_I dA (verification/hertz/
            consistent_fit.py with a second shape term: the coated pressure is not elliptic); uses
            every node's force, not the gap, so it does not see the penalty's overlap;
  pressure_fit  contact_radius_pressure_fit of history.csv (p^2 linear in r^2 through the nodal pressures:
            Hertz's ellipse, which the coated pressure is not);
  node_area sqrt(A/pi) of the node-ring area 4 contact_area (jumps a ring at a time).

and the approach: delta_FE (the tip top's travel) - delta_ref = c + C P + residual, c and C fitted
(the finite column and block add a compliance linear in P; a contact radius off by e adds about
-e delta to the residual, since dP/d delta is the punch stiffness of the contact, ~ a).
Printed per run: the means over the P~ bins 0.02-0.05, 0.05-0.2, 0.2-0.8, > 0.8, the mean |.|, and the
exponent difference b_FE - b_ref fitted over the same rows; --rows prints every row.
"""
import argparse
import csv
import math
import os
import pathlib
import sys

import h5py
import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(ROOT / "tools" / "python"))
from cases import H_C, MIN_LOAD, NU, NU_C, TABLE_B1, ebar  # noqa: E402
from compare_reference import BINS  # noqa: E402
from make_decks import RUNS  # noqa: E402
from results_h5 import si  # noqa: E402

HEX_FACES = [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
GAUSS = 10  # points per direction on a face: the square-root edge inside a face needs more than a few
SHAPE_TERMS = 2  # c0 + c1 (r/a)^2: a third term is ill-conditioned with 3-4 rings of nodes


def materials(name):
    """(R, E, nu, E_c, nu_c, P~ max) in SI of run `name`; the Hertz diagnostic's coating is silicon."""
    run = RUNS[name]
    R, E, Ec, _, pmax = TABLE_B1[run["case"]]
    if run.get("hertz"):
        return R * 1e-9, E * 1e9, NU, E * 1e9, NU, 100.0
    return R * 1e-9, E * 1e9, NU, Ec * 1e9, NU_C, pmax


def slave_faces(f, slave):
    """Faces (4 nodes, counter-clockwise seen from +z) of the hexes whose 4 nodes are all slave nodes."""
    X = si(f["mesh/coordinates"])
    seen = {}
    for e in f["mesh/connectivity"][:]:
        for fc in HEX_FACES:
            q = e[list(fc)]
            if slave[q].all():
                seen[tuple(sorted(q))] = q
    faces = np.array(list(seen.values()))
    for i, q in enumerate(faces):
        c = X[q, :2].mean(axis=0)
        faces[i] = q[np.argsort(np.arctan2(X[q, 1] - c[1], X[q, 0] - c[0]))]
    return faces


class FaceIntegrals:
    """int v N_I dA over the slave faces near the axis (bilinear N_I, GAUSS^2 points per face)."""

    def __init__(self, faces):
        self.faces = faces
        self.nodes, local = np.unique(faces, return_inverse=True)
        self.local = local.reshape(faces.shape)
        g, w = np.polynomial.legendre.leggauss(GAUSS)
        xi, eta = (v.ravel() for v in np.meshgrid(g, g))
        self.weight = np.outer(w, w).ravel()
        self.N = 0.25 * np.array([(1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta)])
        self.dxi = 0.25 * np.array([-(1 - eta), 1 - eta, 1 + eta, -(1 + eta)])
        self.deta = 0.25 * np.array([-(1 - xi), -(1 + xi), 1 + xi, 1 - xi])

    def at(self, x):
        """Area weights dA and squared axis distance rho2 at every face point, positions x."""
        xy = x[self.faces][:, :, :2]
        d = lambda dn, k: np.einsum("aq,fa->fq", dn, xy[:, :, k])  # noqa: E731
        self.dA = np.abs(d(self.dxi, 0) * d(self.deta, 1) - d(self.dxi, 1) * d(self.deta, 0)) * self.weight[None, :]
        self.rho2 = d(self.N, 0) ** 2 + d(self.N, 1) ** 2

    def nodal(self, values):
        out = np.zeros(len(self.nodes))
        for k in range(4):
            np.add.at(out, self.local[:, k], (self.N[k][None, :] * values).sum(axis=1))
        return out


def consistent_fit(fi, force, reach):
    """Radius a of p = sqrt(1 - r^2/a^2)_+ sum_k c_k (r/a)^(2k) best fitting the nodal forces (c_k by
    linear least squares, a by golden section over [0.6, 1.6] x the farthest node with force)."""
    def residual(a):
        base = np.sqrt(np.clip(1 - fi.rho2 / a**2, 0, None)) * fi.dA
        M = np.array([fi.nodal(base * (fi.rho2 / a**2) ** k) for k in range(SHAPE_TERMS)]).T
        c = np.linalg.lstsq(M, force, rcond=None)[0]
        return ((force - M @ c) ** 2).sum()
    lo, hi = 0.6 * reach, 1.6 * reach
    for _ in range(50):
        m1, m2 = lo + 0.382 * (hi - lo), lo + 0.618 * (hi - lo)
        lo, hi = (lo, m2) if residual(m1) < residual(m2) else (m1, hi)
    return 0.5 * (lo + hi)


def edge_crossings(faces, g, positions):
    """Mean axis distance of the gap's sign changes along the face edges (as contact_radius_edge:
    each face's edges from inside to outside, linear in g), located with `positions`."""
    r = []
    for q in faces:
        for k in range(4):
            a, b = q[k], q[(k + 1) % 4]
            if g[a] < 0 <= g[b]:
                t = g[a] / (g[a] - g[b])
                p = positions[a] + t * (positions[b] - positions[a])
                r.append(math.hypot(p[0], p[1]))
    return sum(r) / len(r) if r else float("nan")


def loading_outputs(folder):
    """The run's field outputs on its loading branch, as dicts (time, P, delta, edge, X, x, g, force, slave) with
    P > 0 and at least three slave nodes carrying force, up to the deepest approach; and the FaceIntegrals of the
    slave faces (left at the last output's positions). force: the nodal contact forces along z (N)."""
    hist = list(csv.DictReader(open(os.path.join(folder, "history.csv"))))
    ht = np.array([float(r["time"]) for r in hist])
    outputs = []
    with h5py.File(os.path.join(folder, "results.h5"), "r") as f:
        X = si(f["mesh/coordinates"])
        keys = sorted(f["steps"].keys())
        slave = ~np.isnan(f["steps"][keys[-1]]["nodal/gap"][:])
        fi = FaceIntegrals(slave_faces(f, slave))
        for key in keys:
            st = f["steps"][key]
            i = int(np.argmin(abs(ht - st.attrs["time"])))
            P = 4 * float(hist[i]["contact_normal_force"])
            if abs(ht[i] - st.attrs["time"]) > 1e-14 or P <= 0:
                continue
            x = X + si(st["nodal/displacement"])
            fi.at(x)
            force = np.maximum(-st["nodal/contact_traction"][:][fi.nodes, 2] * fi.nodal(fi.dA), 0.0)
            if np.count_nonzero(force) < 3:
                continue
            outputs.append(dict(time=ht[i], P=P, delta=-float(hist[i]["tip_top_displacement_z"]), hist=hist[i],
                                X=X, x=x, g=si(st["nodal/gap"]), force=force, slave=slave))
    deepest = int(np.argmax([o["delta"] for o in outputs]))
    return outputs[: deepest + 1], fi


def measure(name, folder):
    """Rows (time, P, delta and the ESTIMATORS' radii) at every field output of the run's loading branch, and k_A."""
    outputs, fi = loading_outputs(folder)
    rows = []
    for o in outputs:
        fi.at(o["x"])
        reach = math.sqrt((o["x"][fi.nodes, :2] ** 2).sum(axis=1)[o["force"] > 0].max())
        rows.append(dict(time=o["time"], P=o["P"], delta=o["delta"], edge=float(o["hist"]["contact_radius_edge"]),
                         edge_X=edge_crossings(fi.faces, o["g"], o["X"]), cfit=consistent_fit(fi, o["force"], reach),
                         pressure_fit=float(o["hist"]["contact_radius_pressure_fit"]),
                         node_area=math.sqrt(4 * float(o["hist"]["contact_area"]) / math.pi)))
    return rows, penalty_per_area(folder)


def penalty_per_area(folder):
    """The penalty's stiffness per area k_A = p / overlap at the slave node nearest the axis, last output
    (Pa/m): its compliance 1/k_A is an interface layer the continuum does not have."""
    with h5py.File(os.path.join(folder, "results.h5"), "r") as f:
        X = si(f["mesh/coordinates"])
        st = f["steps"][sorted(f["steps"].keys())[-1]]["nodal"]
        g = si(st["gap"])
        i = int(np.argmin(np.where(np.isnan(g), np.inf, X[:, 0] ** 2 + X[:, 1] ** 2)))
        return float(st["contact_pressure"][i]) / -g[i]


def run_layered(name, tribex, p_tilde, folder, extra=()):
    """`tribex layered` for run `name`'s sphere, coating and substrate at the loads p_tilde (P~), into folder."""
    import subprocess
    R, E, nu, Ec, nuc, _ = materials(name)
    path = os.path.join(folder, "loads.csv")
    with open(path, "w") as fh:
        fh.write("p_tilde\n" + "".join(f"{v:.17g}\n" for v in p_tilde))
    subprocess.run([tribex, "layered", "--radius", f"{R * 1e9:g}nm", "--youngs", f"{E / 1e9:g}GPa", "--poisson", str(nu),
                    "--thickness", f"{H_C}nm", "--layer-youngs", f"{Ec / 1e9:g}GPa", "--layer-poisson", str(nuc),
                    "--substrate-youngs", f"{E / 1e9:g}GPa", "--substrate-poisson", str(nu), "--no-plot", "-o", folder,
                    "--p-tilde-file", path, *extra], check=True, capture_output=True)


def continuum(name, tribex, p_tilde):
    """The layered continuum's contact radius and approach (m) at the loads p_tilde (P~) of run `name`."""
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        run_layered(name, tribex, p_tilde, tmp)
        lines = [ln for ln in open(os.path.join(tmp, "layered.csv")) if not ln.startswith("#")]
    head = [h.split("[")[0] for h in lines[0].strip().split(",")]
    ref = [dict(zip(head, map(float, ln.split(",")))) for ln in lines[1:]]
    return np.array([r["contact_radius"] for r in ref]) * 1e-9, np.array([r["approach"] for r in ref]) * 1e-9


def in_study_range(name, rows):
    """The rows whose load P~ = P / (E_c-bar H_C^2) lies in the study's range and whose edge radius lies between
    3 h and 5 nm - h (h the run's element size), and their P~."""
    R, E, nu, Ec, nuc, pmax = materials(name)
    h = RUNS[name]["h"] * 1e-9
    scale = ebar(Ec, nuc) * (H_C * 1e-9) ** 2
    rows = [r for r in rows if MIN_LOAD <= r["P"] / scale <= pmax and 3 * h <= r["edge"] <= 5e-9 - h]
    return rows, np.array([r["P"] / scale for r in rows])


ESTIMATORS = ("edge", "edge_X", "cfit", "pressure_fit", "node_area")


def diagnose(name, runs, tribex, show_rows):
    """One run: (summary dict, printed lines)."""
    rows, k_a = measure(name, os.path.join(runs, "coated_" + name))
    rows, pn = in_study_range(name, rows)
    a_ref, d_ref = continuum(name, tribex, pn)
    out = dict(run=name, rows=len(rows), p_tilde_lo=pn.min(), p_tilde_hi=pn.max(), penalty_per_area=k_a)
    lines = []
    for k in ESTIMATORS:
        d = np.array([r[k] for r in rows]) ** 2 / a_ref**2 - 1
        for (lo, hi), tag in zip(BINS, ("bin1", "bin2", "bin3", "bin4")):
            sel = (pn >= lo) & (pn < hi)
            out[f"{k}_{tag}"] = d[sel].mean() if sel.any() else float("nan")
        out[f"{k}_mean_abs"] = np.abs(d).mean()
        out[f"{k}_db"] = np.polyfit(np.log(pn), np.log1p(d), 1)[0]
        lines.append(f"  {k:12s} " + " ".join(f"{100 * out[f'{k}_bin{j}']:+6.2f}" for j in range(1, 5))
                     + f"   mean |.| {100 * out[f'{k}_mean_abs']:5.2f} %   b_FE - b_ref {out[f'{k}_db']:+.4f}")
    P = np.array([r["P"] for r in rows])
    dd = np.array([r["delta"] for r in rows]) - d_ref
    c, C = np.linalg.lstsq(np.vstack([np.ones_like(P), P]).T, dd, rcond=None)[0]
    res = (dd - c - C * P) / d_ref
    out.update(approach_C=C, approach_rms=np.sqrt((res**2).mean()),
               **{f"approach_bin{j + 1}": res[(pn >= lo) & (pn < hi)].mean() for j, (lo, hi) in enumerate(BINS)})
    lines.append("  approach: delta_FE - delta_ref = c + C P + residual, C = "
                 f"{C * 1e3:+.3f} pm/nN; residual / delta_ref " + " ".join(f"{100 * out[f'approach_bin{j}']:+6.2f}" for j in range(1, 5))
                 + f"   rms {100 * out['approach_rms']:.2f} %")
    head = (f"{name} ({RUNS[name]['h']:g} nm, k_A = {k_a:.3g} Pa/m; {len(rows)} rows, P~ {pn.min():.3f}-{pn.max():.3f}): f_FE/f_ref - 1 (%) "
            f"over P~ 0.02-0.05, 0.05-0.2, 0.2-0.8, > 0.8")
    if show_rows:
        lines += [f"    P~ {p:.4f}  a_ref {a * 1e9:.3f} nm  " + "  ".join(f"{k} {100 * ((r[k] / a) ** 2 - 1):+6.2f}" for k in ESTIMATORS)
                  for p, a, r in zip(pn, a_ref, rows)]
    return out, [head] + lines


def markdown(results):
    """README.md's table: one row per run, f_FE/f_ref - 1 bins of the edge radius and the consistent fit."""
    pct = lambda v: "-" if math.isnan(v) else f"{100 * v:+.2f}"  # noqa: E731 (a bin the run does not reach)
    lines = ["| run | changed | k_A (Pa/m) | edge radius: bins (%) | mean abs | b_FE - b_ref | consistent fit: bins (%) | "
             "b_FE - b_ref | approach residual, first bin |", "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in results:
        name = r["run"]
        changed = ", ".join(f"{k} {v}" for k, v in DIAGNOSTICS_OF(name).items()) or "none (case1.i)"
        lines.append(f"| {name} | {changed} | {r['penalty_per_area']:.2g} | "
                     + " / ".join(pct(r[f"edge_bin{j}"]) for j in range(1, 5)) + f" | {100 * r['edge_mean_abs']:.2f} | "
                     f"{r['edge_db']:+.4f} | " + " / ".join(pct(r[f"cfit_bin{j}"]) for j in range(1, 5))
                     + f" | {r['cfit_db']:+.4f} | {pct(r['approach_bin1'])} |")
    return "\n".join(lines)


def DIAGNOSTICS_OF(name):
    from make_decks import DIAGNOSTICS  # noqa: E402
    return DIAGNOSTICS.get(name, {})


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", nargs="+", help="deck names (make_decks.RUNS) of runs with field output, e.g. diag_case1")
    ap.add_argument("--runs", default=str(ROOT / "build" / "verification"), help="folder of the coated_<run> folders")
    ap.add_argument("--tribex", default=str(ROOT / "build" / "bin" / "tribex"), help="the tribex binary")
    ap.add_argument("--csv", help="write one row per run")
    ap.add_argument("--rows", action="store_true", help="print every row")
    ap.add_argument("--markdown", action="store_true", help="print the README table of all the runs at the end")
    a = ap.parse_args()
    results = []
    for name in a.run:
        if name not in RUNS:
            print(f"diagnose.py: error: unknown run '{name}' (make_decks.py RUNS)", file=sys.stderr)
            return 2
        out, lines = diagnose(name, a.runs, a.tribex, a.rows)
        results.append(out)
        print("\n".join(lines))
    if a.markdown:
        print(markdown(results))
    if a.csv:
        with open(a.csv, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(results[0].keys()))
            w.writeheader()
            for r in results:
                w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    return 0


if __name__ == "__main__":
    sys.exit(main())
