#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Friction clamp: friction force against normal load with the rough-surface (GW) contact model.

Runs clamp.i once per normal load (the pressure scale factor is replaced), takes the steady-sliding
friction and the normal force from each history, fits F = mu (N + F_adh) (report Eq. 2.2) with
`tribex friction-test static` (the project's Eq. 2.2 fitter), prints mu and F_adh, and checks:
  * quasi-static normal loading: kinetic energy < 2 % of internal energy just before the pull;
  * steady sliding: friction = tau* x real contact area within 0.5 % (tanh(V/v_ref) = tanh(10));
  * mu independent of load within 5 % above the adhesion-dominated range (N > 2 F_adh): the secant
    mu_k = F_k / (N_k + F_adh) of every such load against the fitted mu;
  * each FE point against the GW model evaluated directly (scipy quadrature of F_n; the separation
    solved from the measured normal force): friction within 0.5 %, the model's adhesive force within 0.5 %;
  * the intercept F_adh against the adhesive force of the model (DMT pull 2 pi W R per contacting
    asperity, history adhesive_force) at the lowest load above the adhesion-dominated range, within 5 %.
The last two acceptance checks of issue 10 are NOT met by this model (README.md explains why); the
script reports them and fails when --strict is given.

usage: run_clamp.py [--tribex build/bin/tribex] [--out DIR] [--reduced] [--plot PNG]
"""
import argparse
import math
import json
import os
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "tools" / "python"))
from history_checks import (max_kinetic_over_stored, mean, pyplot, read_history, report_failures,  # noqa: E402
                            rows_between, save_figure)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
FOOT_AREA = 200e-6 * 10e-6          # m^2
TAU_STAR = 1e9                      # Pa, as in clamp.i
LOADS_FULL = [3e-6, 10e-6, 30e-6, 100e-6, 300e-6, 1e-3]   # N (the report's clamp range is 1 uN - 1 mN)
LOADS_REDUCED = [10e-6, 30e-6, 100e-6, 300e-6]
HOLD_END = (550e-9, 600e-9)         # s: settled, before the pull starts at 600 ns
SLIDE = (1000e-9, 1200e-9)          # s: steady sliding at 0.01 m/s
SLIDE_SPEED = 0.01                  # m/s, the pull function's slope


def resolved(log_path):
    """The interaction's parameters in SI from the resolved deck in the run's log.txt."""
    keys = {"summit density": "eta", "summit radius": "R", "summit height deviation": "sigma", "composite modulus": "E",
            "work of adhesion": "W", "junction strength": "tau", "junction reference speed": "v_ref"}
    out = {}
    with open(log_path) as f:
        for line in f:
            k, _, v = line.strip().partition(" = ")
            if k in keys:
                out[keys[k]] = float(v)
    return out


def gw_f(n, t):
    """F_n(t) = (1/sqrt(2 pi)) int_t^inf (s - t)^n exp(-s^2/2) ds (report Eq. 4.9), by scipy quadrature."""
    from scipy import integrate
    value, _ = integrate.quad(lambda s: (s - t) ** n * math.exp(-0.5 * s * s), t, t + 40.0, epsabs=0, epsrel=1e-12, limit=200)
    return value / math.sqrt(2.0 * math.pi)


def gw_at_load(q, load):
    """Direct GW with DMT per asperity for a flat of area FOOT_AREA under `load`: friction, adhesive force."""
    from scipy import optimize
    hertz = q["eta"] * (4.0 / 3.0) * q["E"] * math.sqrt(q["R"]) * q["sigma"] ** 1.5
    pull = q["eta"] * 2.0 * math.pi * q["W"] * q["R"]
    t = optimize.brentq(lambda t: FOOT_AREA * (hertz * gw_f(1.5, t) - pull * gw_f(0.0, t)) - load, -3.0, 5.9, xtol=1e-14)
    area = FOOT_AREA * math.pi * q["eta"] * q["R"] * q["sigma"] * gw_f(1.0, t)
    return q["tau"] * area * math.tanh(SLIDE_SPEED / q["v_ref"]), FOOT_AREA * pull * gw_f(0.0, t), t


def run_load(tribex, deck_text, load, out):
    folder = os.path.join(out, f"load_{load * 1e6:g}uN")
    os.makedirs(folder, exist_ok=True)
    pressure = load / FOOT_AREA
    text, n = re.subn(r"scale factor = [^#\n]*Pa(\s*#\s*NORMAL PRESSURE)", f"scale factor = {pressure:.10g} Pa\\1", deck_text)
    if n != 1:
        sys.exit("run_clamp.py: clamp.i has no 'scale factor = ... Pa  # NORMAL PRESSURE' line")
    deck = os.path.join(folder, "clamp.i")
    with open(deck, "w") as f:
        f.write(text)
    subprocess.run([tribex, "run", deck, "-o", folder, "--quiet"], check=True)
    rows = read_history(folder)
    sliding = rows_between(rows, *SLIDE)
    hold = rows_between(rows, *HOLD_END)
    # Quasi-static check: kinetic energy against the stored energy, elastic plus the GW interface's
    # (contact_work: no friction has dissipated before the pull).
    return {
        "parameters": resolved(os.path.join(folder, "log.txt")),
        "load": load,
        "normal_force": mean(sliding, "contact_normal_force"),
        "friction_force": mean(sliding, "friction_force"),
        "tau_star_times_real_area": TAU_STAR * mean(sliding, "real_contact_area"),
        "adhesive_force": mean(sliding, "adhesive_force"),
        "asperity_contacts": mean(sliding, "asperity_contacts"),
        "kinetic_over_internal": max_kinetic_over_stored(hold, ("internal_energy", "contact_work")),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tribex", default=os.path.join(ROOT, "build", "bin", "tribex"))
    ap.add_argument("--out", default="clamp_friction_output")
    ap.add_argument("--reduced", action="store_true", help="CI form: 4 loads (10 uN - 300 uN)")
    ap.add_argument("--plot", help="PNG of friction against load with the Eq. 2.2 fit")
    ap.add_argument("--strict", action="store_true", help="fail on the mu-independence and intercept checks too")
    a = ap.parse_args()
    with open(os.path.join(HERE, "clamp.i")) as f:
        deck_text = f.read()
    os.makedirs(a.out, exist_ok=True)
    points = [run_load(a.tribex, deck_text, load, a.out) for load in (LOADS_REDUCED if a.reduced else LOADS_FULL)]
    table = os.path.join(a.out, "friction_vs_load.csv")
    with open(table, "w") as f:
        f.write("normal_force[N],friction_force[N]\n")
        for p in points:
            f.write(f"{p['normal_force']:.12g},{p['friction_force']:.12g}\n")
    fit = json.loads(subprocess.run([a.tribex, "friction-test", "static", table, "--json"], check=True,
                                    capture_output=True, text=True).stdout)
    mu, f_adh = fit["mu_s"]["value"], fit["adhesion_force"]["value"]
    print(f"{'N (uN)':>9} {'F (uN)':>9} {'F_GW':>9} {'dF %':>7} {'F_adh,model':>11} {'F_adh,GW':>9} {'t=d/sig':>7} "
          f"{'asperities':>10} {'mu_k':>7} {'KE/E':>8}")
    failures, acceptance = [], []
    for p in points:
        p["mu_secant"] = p["friction_force"] / (p["normal_force"] + f_adh)
        friction_gw, adhesive_gw, t = gw_at_load(p["parameters"], p["normal_force"])
        err_f = p["friction_force"] / friction_gw - 1
        err_a = p["adhesive_force"] / adhesive_gw - 1
        print(f"{p['normal_force'] * 1e6:9.4g} {p['friction_force'] * 1e6:9.4g} {friction_gw * 1e6:9.4g} {100 * err_f:7.3f} "
              f"{p['adhesive_force'] * 1e6:11.4g} {adhesive_gw * 1e6:9.4g} {t:7.3f} {p['asperity_contacts']:10.4g} "
              f"{p['mu_secant']:7.4f} {p['kinetic_over_internal']:8.1e}")
        if abs(err_f) > 0.005 or abs(err_a) > 0.005:
            failures.append(f"load {p['load']:g} N: friction ({100 * err_f:+.3f} %) or adhesive force ({100 * err_a:+.3f} %) "
                            "differs from the direct GW model by more than 0.5 %")
        if p["kinetic_over_internal"] > 0.02:
            failures.append(f"load {p['load']:g} N: kinetic energy {100 * p['kinetic_over_internal']:.2f} % of internal before the pull (> 2 %)")
        if abs(p["friction_force"] / p["tau_star_times_real_area"] - 1) > 0.005:
            failures.append(f"load {p['load']:g} N: friction differs from tau* x real area by more than 0.5 %")
    print(f"Eq. 2.2 fit (tribex friction-test static): mu = {mu:.4f} +- {fit['mu_s']['uncertainty']:.2g}, "
          f"F_adh = {f_adh * 1e6:.4g} +- {fit['adhesion_force']['uncertainty'] * 1e6:.2g} uN")
    above = [p for p in points if p["normal_force"] > 2 * f_adh]
    worst = max(abs(p["mu_secant"] / mu - 1) for p in above) if above else float("nan")
    print(f"mu independence above the adhesion-dominated range (N > 2 F_adh, {len(above)} loads): "
          f"worst |mu_k / mu - 1| = {100 * worst:.2f} % (5 %)")
    if not above or worst > 0.05:
        acceptance.append(f"mu depends on load by {100 * worst:.2f} % (> 5 %)")
    # The model's adhesive force where the fit's offset matters: at the lowest load above the range.
    ref = min(above, key=lambda p: p["normal_force"]) if above else points[0]
    ratio = f_adh / ref["adhesive_force"]
    print(f"intercept F_adh = {f_adh * 1e6:.4g} uN against the model's adhesive force {ref['adhesive_force'] * 1e6:.4g} uN "
          f"at N = {ref['normal_force'] * 1e6:.4g} uN: ratio {ratio:.3f} (1 +- 0.05)")
    if abs(ratio - 1) > 0.05:
        acceptance.append(f"intercept F_adh differs from the model's adhesive force by {100 * (ratio - 1):+.1f} % (> 5 %)")
    if a.plot:
        fig, (ax, ax_log) = pyplot().subplots(1, 2, figsize=(10, 4))
        n = [p["normal_force"] * 1e6 for p in points]
        f = [p["friction_force"] * 1e6 for p in points]
        x = [-f_adh * 1e6] + n
        for axis in (ax, ax_log):
            axis.plot(n, f, "o", label="FE, steady sliding (= direct GW)")
            axis.plot(x[1:] if axis is ax_log else x, [mu * (v + f_adh * 1e6) for v in (x[1:] if axis is ax_log else x)], "-",
                      label=f"Eq. 2.2 fit: mu = {mu:.3f}, F_adh = {f_adh * 1e6:.3g} uN")
            axis.plot(n, [p["adhesive_force"] * 1e6 for p in points], "s--", ms=3, label="adhesive force of the model")
            axis.set_xlabel("normal load N (uN)")
            axis.set_ylabel("force (uN)")
        ax_log.set_xscale("log")
        ax_log.set_yscale("log")
        ax.legend(fontsize=8)
        save_figure(fig, a.plot, announce=None)
    for f in acceptance:
        print("NOT MET (issue 10 acceptance):", f)
    status = report_failures(failures)
    return 1 if status or (a.strict and acceptance) else 0


if __name__ == "__main__":
    sys.exit(main())
