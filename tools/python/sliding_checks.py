# SPDX-License-Identifier: MIT
"""Steady sliding of a tip with the junction model (docs/theory.md 7): the window figures and checks
shared by verification/sphere_sliding/compare.py and inputs/examples/afm_sliding/afm_sliding.py.

The tip top is driven along `axis` (x or y); the sliding distance is the history column
tip_top_displacement_<axis>. Columns used: friction_force (magnitude of the summed junction shear),
tau_star_times_area (tau* x FE contact area: the friction when every contacting pair slips),
contact_normal_force, contact_area, kinetic_energy, internal_energy, substrate_bottom_reaction_<axis>.
"""
import math

from history_checks import max_kinetic_over_stored, mean


def steady_window(rows, axis, s0, s1=math.inf):
    """Means over the rows whose sliding distance is in [s0, s1] (m): a dict with rows, F (friction),
    capacity (tau* A_FE), P (contact normal force), area, base (substrate base reaction along axis),
    worst_row (largest |F / (tau* A_FE) - 1| of a row), ke_ie (largest kinetic / internal energy).
    None when no row is in the window."""
    window = [r for r in rows if s0 <= r[f"tip_top_displacement_{axis}"] <= s1]
    if not window:
        return None
    return {
        "rows": window,
        "F": mean(window, "friction_force"),
        "capacity": mean(window, "tau_star_times_area"),
        "P": mean(window, "contact_normal_force"),
        "area": mean(window, "contact_area"),
        "base": mean(window, f"substrate_bottom_reaction_{axis}"),
        "worst_row": max(abs(r["friction_force"] / r["tau_star_times_area"] - 1) for r in window),
        "ke_ie": max_kinetic_over_stored(window),
    }


def base_reaction_failure(window, axis):
    """The failure message when the substrate's base reaction does not oppose the friction that drags
    the substrate in +axis (it must be below -F/2), else None."""
    if window["base"] < -0.5 * window["F"]:
        return None
    return (f"base reaction {axis} {window['base']:.4g} N does not oppose the friction dragging the "
            f"substrate in +{axis}")


def sliding_rows(rows, axis):
    """The rows after sliding has started (distance above 1e-13 m), for plots against distance."""
    return [r for r in rows if r[f"tip_top_displacement_{axis}"] > 1e-13]


def friction_radius_axes(plt):
    """The figure of both scripts: friction force (top) and contact radius (bottom) against the
    sliding distance, sharing the x axis."""
    return plt.subplots(2, 1, figsize=(6, 6), sharex=True)
