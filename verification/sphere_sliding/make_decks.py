#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes sphere_sliding_coarse.i (CI) and sphere_sliding_fine.i (label slow) from one template, so
the two variants differ only in the mesh and the sliding schedule. Run it after editing the template:

    /usr/bin/python3 verification/sphere_sliding/make_decks.py

The tip top follows cycloidal velocity ramps (v = V (1 - cos(pi t / T)) / 2 over T = 40 ps, zero
acceleration jump at both ends) written as piecewise-linear tables at 5 ps (tools/python/deck_templates.py
holds the ramps, the tables and the deck blocks shared with the other make_decks.py).
"""
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from deck_templates import (HEX8_FULLY_INTEGRATED, PS, block_parameters, elastic_material,  # noqa: E402
                            contact_definition, fixed_displacement, function_table, history_output, piecewise_linear_function,
                            prescribed, ramped_travel, results_output, table_times, write_deck)

RAMP = 40 * PS
SILICON = elastic_material("silicon", 2330, 161, 0.23)


TEMPLATE = """\
# {name}.i -- written by make_decks.py (edit that, not this file).
# A silicon sphere (R = 27 nm) indented into a silicon flat, held, then slid tangentially with the
# junction model (issue 4 acceptance): W = 0.05 J/m^2, z0 = 0.3 nm (as verification/dmt), tau* = 195 MPa.
#
# Run:    build/bin/tribex run verification/sphere_sliding/{name}.i -o {name}_output
# Check:  /usr/bin/python3 verification/sphere_sliding/compare.py {name}_output --window {window}
#
# Procedure (one deck, one time line; the two stages are functions of time on the tip top):
#   0 - {t_indent:.0f} ps   indent: tip top pushed down {depth} nm (cycloidal ramps, {v_indent} m/s)
#   {t_indent:.0f} - {t_slide:.0f} ps  hold: displacement hold of the tip top (not load control: the tip
#                     top's z stays prescribed; the normal load is the contact normal force,
#                     measured, and it drifts by about 1 % while sliding: tau* is 2 % of the
#                     mean contact pressure)
#   {t_slide:.0f} - {t_end:.0f} ps  slide in +x at {v_slide} m/s ({distance:.2f} nm), the z hold kept.
# Expected in steady sliding: friction = tau* pi a^2, a = DMT radius at the contact normal force P,
#   a^3 = 3 R (P + 2 pi W R) / (4 E*), E* = E / (2 (1 - nu^2)) = 85.0 GPa.
# In contact: where the gap interpolated over the tip-surface faces is <= 0 (junction gap tolerance
# = 0: with penalty contact the constraint is active for g < 0; the default g_j = 0.05 z0 would add
# the annulus where the Hertz gap is below 0.015 nm, about 0.45 nm wide here, +20 % area); the shear
# acts on each node's share of that area (contact/models/README.md).
# Quasi-static: mass damping {damping} 1/s (about half critical for the column's axial mode, as in
# verification/hertz); compare.py checks kinetic / internal energy below 2 % in the steady window. The
# damping drags the sliding tip (c M V); the driver carries it, the interface shear does not.
begin sierra {name}
{push_function}
{slide_function}

{silicon}

  # Fully integrated at GPa contact pressures (verification/hertz/README.md: penalty point forces
  # excite the hourglass modes of one-point elements).
{hex8}

  begin finite element model asperity
    begin generated asperity
      radius = 27 nm
      tip width = {tip_width} nm
      tip height = {tip_height} nm
      substrate width = {substrate_width} nm
      substrate depth = {substrate_depth} nm
      element size = {h} nm
      fine half width = {fine_half_width} nm   # the contact (a ~ 4.5 nm) slides {distance:.1f} nm in +x and stays inside
      fine depth = {fine_depth} nm
      grading ratio = {grading}
    end generated asperity
{blocks}
  end finite element model asperity

  begin presto procedure indent_hold_slide
    begin time control
      termination time = {t_end:.1f} ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = {damping} 1/s
      quasi static = on             # run guards: kinetic energy below 5 % of internal energy while loaded
{boundary_conditions}
{contact}
{outputs}
    end presto region main
  end presto procedure indent_hold_slide
end sierra {name}
"""

# Junction model on the tip-flat pair (the same in both variants).
JUNCTION = """\
          model = junction
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm        # 20 z0: the law keeps 99 % of W (docs/theory.md 6.3)
          junction strength = 195 MPa
          junction reference speed = 0.1 m/s   # no stability floor (backward Euler): tanh(V/v_ref) = 1 in sliding
          junction gap tolerance = 0 nm
"""

VARIANTS = {
    # CI: small substrate, 0.8 nm elements (as dmt_coarse), 1.8 nm of sliding at 10 m/s.
    "sphere_sliding_coarse": dict(h=0.8, tip_width=24, tip_height=13, substrate_width=40, substrate_depth=20,
                                  fine_half_width=9.6, fine_depth=3.2, grading=1.4, v_indent=10.0, depth=0.72,
                                  hold=10, v_slide=10.0, distance=1.8, damping="5e11", history=2, fields=50,
                                  window="0.2 1.8"),
    # slow: 0.5 nm elements, larger substrate, 2.4 nm of sliding at 10 m/s.
    "sphere_sliding_fine": dict(h=0.5, tip_width=24, tip_height=13, substrate_width=48, substrate_depth=24,
                                fine_half_width=9.5, fine_depth=3.0, grading=1.3, v_indent=8.0, depth=0.72,
                                hold=20, v_slide=10.0, distance=2.4, damping="5e11", history=2, fields=50,
                                window="0.4 2.4"),
}


def main():
    here = pathlib.Path(__file__).resolve().parent
    blocks = block_parameters("tip", "silicon") + "\n" + block_parameters("substrate", "silicon")
    boundary_conditions = "\n".join([
        fixed_displacement("substrate_bottom", "x y z"), fixed_displacement("tip_top", "y"),
        prescribed("displacement", "tip_top", "z", "push", "-1"), prescribed("displacement", "tip_top", "x", "slide")])
    for name, v in VARIANTS.items():
        depth = v["depth"] * 1e-9
        t_indent = depth / v["v_indent"] + RAMP
        t_slide = t_indent + v["hold"] * PS
        # constant speed after the up-ramp; the slide ends at `distance`
        t_end = t_slide + RAMP + (v["distance"] * 1e-9 - v["v_slide"] * RAMP / 2) / v["v_slide"]
        t_end = math.ceil(t_end / PS)  * PS
        push = function_table(lambda t: ramped_travel(t, v["v_indent"], 0.0, t_indent), table_times(t_indent), "7.1f")
        push += f"\n{t_end / PS:9.1f}  {v['depth']:.5f}"
        slide = function_table(lambda t: ramped_travel(t, v["v_slide"], t_slide), table_times(t_end, t_slide), "7.1f")
        text = TEMPLATE.format(name=name, push_function=piecewise_linear_function("push", push),
                               slide_function=piecewise_linear_function("slide", slide), silicon=SILICON,
                               hex8=HEX8_FULLY_INTEGRATED, blocks=blocks,
                               boundary_conditions=boundary_conditions,
                               contact=contact_definition("tip_on_flat", [("tip", "tip_surface"), ("flat", "substrate_top")],
                                                          "0 0 0 0 0 1", "sphere_flat", JUNCTION),
                               outputs=history_output(v["history"], "tip_top substrate_bottom", "tip_top tip_apex")
                               + "\n" + results_output(v["fields"]), t_indent=t_indent / PS,
                               t_slide=t_slide / PS, t_end=t_end / PS, **v)
        write_deck(here, name, text)
        print(f"{name}.i: indent to {t_indent / PS:.0f} ps, slide from {t_slide / PS:.0f} ps, end {t_end / PS:.0f} ps")


if __name__ == "__main__":
    main()
