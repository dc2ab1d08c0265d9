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


RADIUS_ESTIMATORS = ("pressure_fit", "edge")  # history columns contact_radius_<estimator>


def print_unchecked_radius(rows, reference, checked):
    """Prints the error against `reference` (one radius per row) of the contact-radius estimator
    that is not `checked`, for information."""
    other = "contact_radius_edge" if checked == "pressure_fit" else "contact_radius_pressure_fit"
    worst, average = max_and_mean(relative_errors([r[other] for r in rows], reference))
    print(f"  (not checked: {other} max error {worst:.2%}, mean {average:.2%})")
