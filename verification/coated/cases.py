# SPDX-License-Identifier: MIT
"""The seven cases of the report's Table B.1 (the Sandia report "High Fidelity Frictional Models for MEMS", Appendix B; docs/theory.md 11) and the runs of this study.

One table, read by make_decks.py (writes the decks) and study.py (fits A, b). Units: nm, GPa, nN.
Table B.1 lists R, E_c, Ebar_c/Ebar, h_c/R, nu, nu_c and the largest P/(Ebar_c h_c^2) of the fit;
h_c = (h_c/R) R = 2.0 nm in every case and E = 161 GPa except case 7, where both moduli are doubled
(E_c = 16 GPa at Ebar_c/Ebar = 0.056 needs E = 322 GPa). A and b are withheld: we compute them.
"""

NU, NU_C = 0.23, 0.40
H_C = 2.0  # coating thickness, nm
Z0 = 0.3  # equilibrium separation of the adhesion runs, nm (make_decks.py; h_c = 6 nm = 20 z0)

# case: (R nm, E GPa, E_c GPa, Table B.1 Ebar_c/Ebar, max P/(Ebar_c h_c^2))
TABLE_B1 = {
    1: (27.0, 161.0, 8.0, 0.0560, 1.59),
    2: (30.0, 161.0, 8.0, 0.0560, 1.74),
    3: (35.0, 161.0, 8.0, 0.0560, 1.97),
    4: (27.0, 161.0, 2.0, 0.0140, 2.33),
    5: (27.0, 161.0, 4.0, 0.0280, 2.01),
    6: (27.0, 161.0, 16.0, 0.1120, 1.12),
    7: (27.0, 322.0, 16.0, 0.0560, 1.59),
}
MIN_LOAD = 0.02  # the report's lower end of P/(Ebar_c h_c^2) (Section 3.3)


def ebar(e, nu):
    return e / (1.0 - nu * nu)


def hertz_area(P, R, E, Ec, nu=NU, nu_c=NU_C):
    """pi (3 P R (1 + Ebar/Ebar_c) / (4 Ebar))^(2/3): Eq. B.1 without f (SI)."""
    import math
    Eb, Ecb = ebar(E, nu), ebar(Ec, nu_c)
    return math.pi * (3.0 * P * R * (1.0 + Eb / Ecb) / (4.0 * Eb)) ** (2.0 / 3.0)


def f_deep(E, Ec, nu=NU, nu_c=NU_C):
    """f when the coating is vanishingly thin: (2/(1 + Ebar/Ebar_c))^(2/3) (Appendix B)."""
    return (2.0 / (1.0 + ebar(E, nu) / ebar(Ec, nu_c))) ** (2.0 / 3.0)
