#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The coated study's adhesion collapse states its DMT assumption (verification/coated/study.py
collapse_regime, tools/python/contact_theory.py): case 1 with W = 0.05 and 0.10 J/m^2 lies at mu_T
0.070-0.313 and 0.111-0.497 (Si substrate - coating alone) and warns in one line; W = 0.02 does not.
Exit 0 when every check holds, else prints FAIL lines and exits 1."""
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "verification" / "coated"))
sys.path.insert(0, str(ROOT / "tools" / "python"))
import study  # noqa: E402
from contact_theory import tabor_parameter  # noqa: E402

fails = []


def near(what, got, want, tol):
    if abs(got - want) > tol:
        fails.append(f"FAIL: {what} = {got:.5g}, expected {want:.5g} +- {tol:g}")


near("Si tabor (docs/theory.md 8.5)", tabor_parameter(27e-9, 0.05, 161e9 / (2 * (1 - 0.23 ** 2)), 0.3e-9), 0.0702, 5e-4)
for w, lo, hi in ((0.05, 0.0702, 0.3132), (0.10, 0.1114, 0.4973)):
    m = dict(name=f"case1_w{w:.2f}", R=27e-9, E=161e9, Ec=8e9, W=w)
    got_lo, got_hi, warning = study.collapse_regime(m)
    near(f"W {w} mu_T on Si", got_lo, lo, 5e-4)
    near(f"W {w} mu_T on the coating", got_hi, hi, 5e-4)
    if "assumes DMT (mu_T <= 0.3) but mu_T = " not in warning or "\n" in warning:
        fails.append(f"FAIL: W {w}: no one-line DMT warning: {warning!r}")
quiet = study.collapse_regime(dict(name="case1_w0.02", R=27e-9, E=161e9, Ec=8e9, W=0.02))
if quiet[2]:
    fails.append(f"FAIL: W 0.02 (mu_T {quiet[1]:.3g}) warned: {quiet[2]!r}")
print("\n".join(fails) if fails else "coated collapse regime: PASS")
sys.exit(1 if fails else 0)
