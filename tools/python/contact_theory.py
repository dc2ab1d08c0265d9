# SPDX-License-Identifier: MIT
"""Sphere-on-flat contact references shared by the compare scripts (docs/theory.md 8.2), SI units."""
import math

from history_checks import max_and_mean, relative_errors


def effective_modulus(E, nu):
    """E* = E / (2 (1 - nu^2)) for two bodies of the same material."""
    return E / (2 * (1 - nu * nu))


def dmt_radius(P, R, W, estar):
    """DMT contact radius a^3 = 3 R (P + 2 pi W R) / (4 E*) (0 below the pull-off); W = 0: Hertz."""
    return (3 * R * max(P + 2 * math.pi * W * R, 0.0) / (4 * estar)) ** (1 / 3)


# Where DMT and JKR stop holding for the Lennard-Jones law (tools/common/tabor.hpp holds the same numbers
# for the C++ tools; tools/adhesion/README.md, regression table: 1.86 pi W R at mu_T = 0.3, 1.54 at 3).
DMT_MAX_TABOR = 0.3
JKR_MIN_TABOR = 3.0


def tabor_parameter(R, W, estar, z0):
    """mu_T = (R W^2 / (E*^2 z0^3))^(1/3) (docs/theory.md 8.5), SI."""
    return (R * W * W / (estar * estar * z0 ** 3)) ** (1 / 3)


def dmt_regime_warning(tabor, who, where, advice):
    """"" when tabor <= DMT_MAX_TABOR, else one line: WHO assumes DMT but mu_T = ... (WHERE); ADVICE."""
    if not tabor > DMT_MAX_TABOR:
        return ""
    return (f"warning: {who} assumes DMT (mu_T <= {DMT_MAX_TABOR:g}) but mu_T = {tabor:.3g} ({where}): the pull-off "
            f"there lies between 1.5 and 2 pi W R and below the DMT 2 pi W R (tools/adhesion/README.md); {advice}")


# The contact-radius estimators, by the name --radius takes, and their history columns
# (solver/output/history_columns.cpp; errors on the Hertz decks: verification/hertz/README.md, "The
# contact-radius estimators"): the elliptic fit of the nodal pressures, the gap sign change on
# slave-face edges, sqrt(contact_area/pi), and the plain column, which is the edge one where that is
# defined (a contact axis) and the area one elsewhere.
RADIUS_COLUMNS = {"pressure_fit": "contact_radius_pressure_fit", "edge": "contact_radius_edge",
                  "area": "contact_radius_area", "plain": "contact_radius"}
RADIUS_ESTIMATORS = tuple(RADIUS_COLUMNS)


def radius_column(estimator):
    """The history column of a contact-radius estimator (a key of RADIUS_COLUMNS)."""
    return RADIUS_COLUMNS[estimator]


def print_unchecked_radius(rows, reference, checked):
    """Prints the error against `reference` (one radius per row) of each contact-radius column that
    is not the `checked` one, for information."""
    for name, column in RADIUS_COLUMNS.items():
        if name == checked or column not in rows[0]:
            continue
        worst, average = max_and_mean(relative_errors([r[column] for r in rows], reference))
        print(f"  (not checked: {column} max error {worst:.2%}, mean {average:.2%})")
