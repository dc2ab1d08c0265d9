#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Friction clamp: friction force against normal load with the rough-surface (GW) contact model, in
three variants of the interaction (issue 26):
  hertz           GW with Hertz asperities (no adhesion);
  dmt             GW with DMT adhesion per contacting asperity, W = 0.1 J/m^2 (report Eq. 4.10; clamp.i);
  dmt_noncontact  the same plus the attraction of the non-contacting area (docs/theory.md 10.8,
                  `noncontact equilibrium separation = 0.2 nm`).
For each variant: clamp.i runs once per normal load (the pressure scale factor is replaced), the
steady-sliding friction and normal force are taken from each history, F = mu (N + F_adh) (report
Eq. 2.2) is fitted with `tribex friction-test static`, and F_adh is given per apparent area beside the
report's 1 nN/um^2 (and its measured line F = 0.28 (N + 1 nN/um^2 x A), Section 2.1.3, on the plot).
Checks (failures exit 1):
  * quasi-static normal loading: kinetic energy < 2 % of the stored energy just before the pull;
  * steady sliding: friction = tau* x real contact area within 0.5 % (tanh(V/v_ref) = tanh(10));
  * every FE point equals the model evaluated directly (scipy quadrature of F_n and of the attraction,
    the separation solved from the measured normal force): friction and adhesive force within 0.5 %.
How constant mu and the offset are over the loads is printed (secant mu_k = F / (N + F_adh)), as measured.

usage: run_clamp.py [--tribex build/bin/tribex] [--out DIR] [--reduced] [--variants V,...] [--plot PNG]
"""
import argparse
import json
import math
import os
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "tools" / "python"))
from history_checks import finish_axes, mean, pyplot, read_history, report_failures, rows_between, save_figure  # noqa: E402
from rough_theory import gw_integral, noncontact_attraction  # noqa: E402
from cli_errors import InputError, guarded, make_folder, require_executable  # noqa: E402

MADE = []  # output folders this run created: removed again on bad input

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
FOOT_AREA = 200e-6 * 10e-6          # m^2
TAU_STAR = 1e9                      # Pa, as in clamp.i
LOADS_FULL = [3e-6, 10e-6, 30e-6, 100e-6, 300e-6, 1e-3]   # N (the report's clamp range is 1 uN - 1 mN)
LOADS_REDUCED = [10e-6, 30e-6, 100e-6, 300e-6]
HOLD_END = (550e-9, 600e-9)         # s: settled, before the pull starts at 600 ns
SLIDE = (1000e-9, 1200e-9)          # s: steady sliding at 0.05 m/s (the pull spring stretched by 600-850 ns)
SLIDE_SPEED = 0.05                  # m/s, the pull function's slope
NONCONTACT_Z0, NONCONTACT_CUTOFF = 0.2e-9, 200 * 0.2e-9   # m: the variant's z0 and the default cut-off
REPORT_MU_D, REPORT_ADHESION = 0.28, 1e-9 / 1e-12          # report Section 2.1.3: mu_d, 1 nN/um^2 (N/m^2)
VARIANTS = ("hertz", "dmt", "dmt_noncontact")
W_LINE = "          work of adhesion = 0.1 J/m^2\n"


def variant_deck(text, variant):
    """clamp.i for one variant: without W (Hertz asperities), as it is (DMT), or with the attraction."""
    if W_LINE not in text:
        sys.exit("run_clamp.py: clamp.i has no 'work of adhesion = 0.1 J/m^2' line")
    if variant == "hertz":
        return text.replace(W_LINE, "")
    if variant == "dmt_noncontact":
        return text.replace(W_LINE, W_LINE + f"          noncontact equilibrium separation = {NONCONTACT_Z0 * 1e9:g} nm\n")
    return text


def resolved(log_path):
    """The interaction's parameters in SI from the resolved deck in the run's log.txt."""
    keys = {"summit density": "eta", "summit radius": "R", "summit height deviation": "sigma", "composite modulus": "E",
            "work of adhesion": "W", "junction strength": "tau", "junction reference speed": "v_ref",
            "noncontact equilibrium separation": "z0"}
    out = {"W": 0.0}
    with open(log_path) as f:
        for line in f:
            k, _, v = line.strip().partition(" = ")
            if k in keys:
                out[keys[k]] = float(v)
    return out


def direct_model(q, load):
    """The model for the foot under `load`, evaluated directly: friction, adhesive force (DMT pull plus
    the attraction), t = d / sigma_s."""
    from scipy import optimize
    hertz = q["eta"] * (4.0 / 3.0) * q["E"] * math.sqrt(q["R"]) * q["sigma"] ** 1.5
    dmt = q["eta"] * 2.0 * math.pi * q["W"] * q["R"]

    def pull(t):
        attraction = noncontact_attraction(t * q["sigma"], q["W"], q["z0"], NONCONTACT_CUTOFF, q["sigma"]) if "z0" in q else 0.0
        return dmt * gw_integral(0.0, t) + attraction

    t = optimize.brentq(lambda t: FOOT_AREA * (hertz * gw_integral(1.5, t) - pull(t)) - load, -3.0, 5.9, xtol=1e-14)
    area = FOOT_AREA * math.pi * q["eta"] * q["R"] * q["sigma"] * gw_integral(1.0, t)
    return q["tau"] * area * math.tanh(SLIDE_SPEED / q["v_ref"]), FOOT_AREA * pull(t), t


def run_load(tribex, deck_text, load, out):
    folder = os.path.join(out, f"load_{load * 1e6:g}uN")
    os.makedirs(folder, exist_ok=True)
    text, n = re.subn(r"scale factor = [^#\n]*Pa(\s*#\s*NORMAL PRESSURE)", f"scale factor = {load / FOOT_AREA:.10g} Pa\\1",
                      deck_text)
    if n != 1:
        sys.exit("run_clamp.py: clamp.i has no 'scale factor = ... Pa  # NORMAL PRESSURE' line")
    deck = os.path.join(folder, "clamp.i")
    with open(deck, "w") as f:
        f.write(text)
    subprocess.run([tribex, "run", deck, "-o", folder, "--quiet"], check=True)
    rows = read_history(folder)
    sliding = rows_between(rows, *SLIDE)
    # Quasi-static check: kinetic energy against the stored energy, elastic plus the GW interface's
    # (|contact_work|: no friction has dissipated before the pull; the attraction's work is negative).
    hold = rows_between(rows, *HOLD_END)
    return {
        "parameters": resolved(os.path.join(folder, "log.txt")),
        "load": load,
        "normal_force": mean(sliding, "contact_normal_force"),
        "friction_force": mean(sliding, "friction_force"),
        "tau_star_times_real_area": TAU_STAR * mean(sliding, "real_contact_area"),
        "adhesive_force": mean(sliding, "adhesive_force"),
        "asperity_contacts": mean(sliding, "asperity_contacts"),
        "kinetic_over_stored": max(r["kinetic_energy"] / max(r["internal_energy"] + abs(r["contact_work"]), 1e-300)
                                   for r in hold),
    }


def fit_variant(tribex, points, out, variant):
    table = os.path.join(out, f"friction_vs_load_{variant}.csv")
    with open(table, "w") as f:
        f.write("normal_force[N],friction_force[N]\n")
        for p in points:
            f.write(f"{p['normal_force']:.12g},{p['friction_force']:.12g}\n")
    fit = json.loads(subprocess.run([tribex, "friction-test", "static", table, "--json"], check=True,
                                    capture_output=True, text=True).stdout)
    return fit["mu_s"]["value"], fit["mu_s"]["uncertainty"], fit["adhesion_force"]["value"], fit["adhesion_force"]["uncertainty"]


def check_points(variant, points, f_adh, failures):
    print(f"{'N (uN)':>9} {'F (uN)':>9} {'F_direct':>9} {'dF %':>7} {'F_adh,model':>11} {'direct':>9} {'t=d/sig':>7} "
          f"{'asperities':>10} {'mu_k':>7} {'KE/E':>8}")
    for p in points:
        p["mu_secant"] = p["friction_force"] / (p["normal_force"] + f_adh)
        friction, adhesive, t = direct_model(p["parameters"], p["normal_force"])
        err_f, err_a = p["friction_force"] / friction - 1, (p["adhesive_force"] / adhesive - 1) if adhesive else 0.0
        print(f"{p['normal_force'] * 1e6:9.4g} {p['friction_force'] * 1e6:9.4g} {friction * 1e6:9.4g} {100 * err_f:7.3f} "
              f"{p['adhesive_force'] * 1e6:11.4g} {adhesive * 1e6:9.4g} {t:7.3f} {p['asperity_contacts']:10.4g} "
              f"{p['mu_secant']:7.4f} {p['kinetic_over_stored']:8.1e}")
        where = f"{variant}, load {p['load']:g} N"
        if abs(err_f) > 0.005 or abs(err_a) > 0.005:
            failures.append(f"{where}: friction ({100 * err_f:+.3f} %) or adhesive force ({100 * err_a:+.3f} %) differs "
                            "from the direct model by more than 0.5 %")
        if p["kinetic_over_stored"] > 0.02:
            failures.append(f"{where}: kinetic energy {100 * p['kinetic_over_stored']:.2f} % of the stored energy before the pull")
        if abs(p["friction_force"] / p["tau_star_times_real_area"] - 1) > 0.005:
            failures.append(f"{where}: friction differs from tau* x real area by more than 0.5 %")


def plot(results, path):
    fig, (ax, ax_log) = pyplot().subplots(1, 2, figsize=(11, 4.5))
    report_adh = REPORT_ADHESION * FOOT_AREA
    for (variant, points, mu, f_adh), marker in zip(results, "os^"):
        n = [p["normal_force"] * 1e6 for p in points]
        for axis in (ax, ax_log):
            line = axis.plot(n, [p["friction_force"] * 1e6 for p in points], marker, label=f"FE {variant}")[0]
            x = ([-f_adh * 1e6] if axis is ax and f_adh > 0 else []) + n
            axis.plot(x, [mu * (v + f_adh * 1e6) for v in x], "-", color=line.get_color(),
                      label=f"fit: mu = {mu:.3f}, F_adh = {f_adh * 1e6:.3g} µN ({f_adh / FOOT_AREA * 1e-3:.3g} nN/µm²)")
    for axis in (ax, ax_log):
        x = sorted({p["normal_force"] * 1e6 for _, points, _, _ in results for p in points})
        axis.plot(x, [REPORT_MU_D * (v + report_adh * 1e6) for v in x], "k--", lw=1,
                  label=f"report, measured: F = {REPORT_MU_D} (N + 1 nN/µm² x A)")
        finish_axes(axis, "normal load N (µN)", "friction force F (µN)")
    ax_log.set_xscale("log")
    ax_log.set_yscale("log")
    ax_log.get_legend().remove()
    ax.set_title("friction clamp on di-5 (A = 2000 µm²)")
    save_figure(fig, path, announce=None)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tribex", default=os.path.join(ROOT, "build", "bin", "tribex"))
    ap.add_argument("--out", default="clamp_friction_output")
    ap.add_argument("--reduced", action="store_true", help="CI form: 4 loads (10 uN - 300 uN)")
    ap.add_argument("--variants", default=",".join(VARIANTS), help="comma-separated subset of " + ", ".join(VARIANTS))
    ap.add_argument("--plot", help="PNG of friction against load with the Eq. 2.2 fits and the report's line")
    a = ap.parse_args()
    variants = a.variants.split(",")
    if any(v not in VARIANTS for v in variants):
        raise InputError(f"run_clamp.py: --variants takes {', '.join(VARIANTS)}, got '{a.variants}'")
    with open(os.path.join(HERE, "clamp.i")) as f:
        deck_text = f.read()
    require_executable(a.tribex, "--tribex", "build tribex (README.md) or give its path with --tribex")
    failures, results = [], []
    for variant in variants:
        out = os.path.join(a.out, variant)
        make_folder(a.out, MADE)
        make_folder(out, MADE)
        deck = variant_deck(deck_text, variant)
        points = [run_load(a.tribex, deck, load, out) for load in (LOADS_REDUCED if a.reduced else LOADS_FULL)]
        mu, mu_sigma, f_adh, f_adh_sigma = fit_variant(a.tribex, points, out, variant)
        print(f"== {variant}")
        check_points(variant, points, f_adh, failures)
        secants = [p["mu_secant"] for p in points]
        offsets = [p["adhesive_force"] for p in points]
        print(f"Eq. 2.2 fit: mu = {mu:.4f} +- {mu_sigma:.2g}, F_adh = {f_adh * 1e6:.4g} +- {f_adh_sigma * 1e6:.2g} uN = "
              f"{f_adh / FOOT_AREA * 1e-3:.4g} nN/um^2 (report: {REPORT_ADHESION * 1e-3:g} nN/um^2); secant mu_k from "
              f"{min(secants):.4f} to {max(secants):.4f} ({100 * (max(secants) / min(secants) - 1):.1f} %); the model's "
              f"adhesive force from {min(offsets) * 1e6:.4g} to {max(offsets) * 1e6:.4g} uN")
        results.append((variant, points, mu, f_adh))
    if a.plot:
        plot(results, a.plot)
    return report_failures(failures)


if __name__ == "__main__":
    sys.exit(guarded(main, MADE))
