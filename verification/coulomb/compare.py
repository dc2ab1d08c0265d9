#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Coulomb friction through the solver (docs/theory.md 7.5): a one-element block pressed on a fixed
flat by N and pulled along it by T(t) on its contact nodes (block_pull.i), against the analytic
response of a rigid block with static and kinetic friction:
  - stick while T < mu_s N: the friction force equals T and the face does not move;
  - slip when T reaches mu_s N (onset: T/N at the first step the face has moved, within 1 % of mu_s);
  - sliding with friction mu_k N on every step after the onset (within 1 %);
  - the friction work, the time integral of friction_power, equals mu_k times the integral of N over
    the slip distance (within 1 %) and the energy the contact took from the bodies, the increase of
    contact_work from the onset on (within 1 %);
  - momentum: the block's x momentum equals the impulse of T minus the friction force (within 1 %),
    and the energy balance closes (|energy_error| < 1e-4 from 0.5 ns on, before which every energy
    is near zero).

usage: compare.py OUTPUT [--plot OUT.png]
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from cli_errors import guarded  # noqa: E402
from history_checks import (finish_axes, history_parser, piecewise_linear, pyplot, read_history,  # noqa: E402
                            report_failures, save_figure, trapezoid)

MU_S, MU_K = 0.5, 0.4                 # the deck's coefficients
PULL = ((0.0, 0.0), (2e-9, 0.0), (6e-9, 0.6e-6), (7e-9, 0.75e-6))  # (s, N): T(t), the deck's `pull` x 1e-6 N
STUCK = 1e-13                          # m: "has not moved" (1e-6 of the 100 nm element)
TOLERANCE = 0.01


def pull(t):
    return piecewise_linear(PULL, t)


def main():
    a = history_parser(__doc__, "PNG: friction and the Coulomb limits against time", "output").parse_args()
    rows = read_history(a.output)
    t = [r["time"] for r in rows]
    normal = [r["contact_normal_force"] for r in rows]
    friction = [r["contact_tangential_force"] for r in rows]
    ux = [r["upper_zmin_displacement_x"] for r in rows]
    failures = []

    onset = next((i for i, u in enumerate(ux) if abs(u) > STUCK), None)
    if onset is None:
        return report_failures(["the block never slid"], verdict=True)
    # Stick: the face has not moved before the onset, and the friction holds T (the face nodes carry T).
    # The step before the onset is the one that slipped (its force moves the face in the next step).
    stick = [i for i in range(onset - 1) if t[i] > PULL[1][0]]
    worst = max(stick, key=lambda i: abs(friction[i] - pull(t[i])))
    stick_err = abs(friction[worst] - pull(t[worst])) / (MU_S * normal[worst])
    print(f"stick: {len(stick)} steps up to t = {t[onset - 2] * 1e9:.4f} ns, face displacement at most "
          f"{max(abs(u) for u in ux[:onset]):.3g} m; worst |friction - T| = {100 * stick_err:.3f} % of mu_s N")
    if stick_err > TOLERANCE:
        failures.append(f"friction differs from T while stuck by {100 * stick_err:.2f} % of mu_s N (> 1 %)")
    # Onset: T/N at the step that slipped (friction mu_k N there; the face moves from the next step).
    ratio = pull(t[onset - 1]) / normal[onset - 1]
    onset_err = ratio / MU_S - 1
    print(f"slip at t = {t[onset - 1] * 1e9:.4f} ns: T/N there {ratio:.5f} against mu_s = {MU_S}: "
          f"{100 * onset_err:+.3f} % (tolerance 1 %)")
    if abs(onset_err) > TOLERANCE:
        failures.append(f"slip starts at T/N = {ratio:.4f}, {100 * onset_err:+.2f} % from mu_s (> 1 %)")
    # Sliding: F = mu_k N on every step after the onset.
    sliding = range(onset - 1, len(rows))
    slide_err = max(abs(friction[i] / (MU_K * normal[i]) - 1) for i in sliding)
    print(f"sliding: {len(sliding)} steps, slip {ux[-1] * 1e9:.3f} nm; worst |F / (mu_k N) - 1| = {100 * slide_err:.4f} % "
          "(tolerance 1 %)")
    if slide_err > TOLERANCE:
        failures.append(f"sliding friction differs from mu_k N by {100 * slide_err:.2f} % (> 1 %)")
    # Work: friction power integrated, against mu_k N du and the energy the contact took.
    work = trapezoid(t, [r["friction_power"] for r in rows])
    coulomb = MU_K * trapezoid(ux[onset - 1:], normal[onset - 1:])
    taken = rows[-1]["contact_work"] - rows[onset - 1]["contact_work"]
    for name, ref in (("mu_k int N du", coulomb), ("contact work from the onset", taken)):
        err = work / ref - 1
        print(f"friction work {work:.6g} J against {name} {ref:.6g} J: {100 * err:+.3f} % (tolerance 1 %)")
        if abs(err) > TOLERANCE:
            failures.append(f"friction work differs from {name} by {100 * err:+.2f} % (> 1 %)")
    impulse = trapezoid(t, [pull(ti) - f for ti, f in zip(t, friction)])
    p_err = rows[-1]["momentum_x"] / impulse - 1
    print(f"momentum x {rows[-1]['momentum_x']:.6g} kg m/s against the impulse of T - F {impulse:.6g}: {100 * p_err:+.3f} % "
          "(tolerance 1 %)")
    if abs(p_err) > TOLERANCE:
        failures.append(f"momentum differs from the impulse by {100 * p_err:+.2f} % (> 1 %)")
    energy = max(abs(r["energy_error"]) for r in rows if r["time"] >= 0.5e-9)
    print(f"max |energy_error| from 0.5 ns on {energy:.3g} (tolerance 1e-4; before, the energies are near zero)")
    if energy > 1e-4:
        failures.append(f"energy error {energy:.3g} (> 1e-4)")

    if a.plot:
        plt = pyplot()
        fig, (top, bottom) = plt.subplots(2, 1, figsize=(6, 6), sharex=True)
        ns = [ti * 1e9 for ti in t]
        top.plot(ns, [pull(ti) * 1e9 for ti in t], "-", lw=1, color="0.6", label="applied T")
        top.plot(ns, [f * 1e9 for f in friction], "-", lw=1.5, label="FE friction force")
        top.plot(ns, [MU_S * n * 1e9 for n in normal], "--", lw=1, label="mu_s N")
        top.plot(ns, [MU_K * n * 1e9 for n in normal], ":", lw=1.5, label="mu_k N")
        finish_axes(top, "", "force (nN)", f"Coulomb block pull: mu_s = {MU_S}, mu_k = {MU_K}")
        bottom.plot(ns, [u * 1e9 for u in ux], "-", lw=1.5, label="slip of the block face")
        finish_axes(bottom, "time (ns)", "displacement (nm)")
        save_figure(fig, a.plot)
    return report_failures(failures, verdict=True)


if __name__ == "__main__":
    sys.exit(guarded(main))
