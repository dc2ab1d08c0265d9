#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the two decks of the force-controlled coated slide (README.md): the same model, the tip top
driven through a rigid body (rigid_slide_rigid.i) or with the node-set load control of before
(rigid_slide_nodeset.i: `prescribed force` on the node set shares the force equally among its nodes).

  /usr/bin/python3 verification/rigid_slide/make_decks.py
"""
import math
import os
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "tools" / "python"))
from deck_templates import (HEX8_FULLY_INTEGRATED, block_parameters, elastic_material,  # noqa: E402
                            fixed_displacement, history_output, prescribed, results_output, rigid_body)

HERE = os.path.dirname(os.path.abspath(__file__))
LOAD_NN = 100.0          # normal load, nN
SLIDE_NM, V_NM_PS = 3.0, 0.01   # 3 nm at 10 m/s
T_LOAD, T_SLIDE, T_RAMP = 80.0, 120.0, 40.0  # ps: load ramp, slide start, speed ramp


def load_rows():
    rows = [(T_LOAD * k / 8, k / 8 - math.sin(2 * math.pi * k / 8) / (2 * math.pi)) for k in range(9)]
    return rows + [(1000.0, 1.0)]


def slide_rows():
    """x(t): at rest to T_SLIDE, a cycloidal speed ramp to V over T_RAMP, then V to SLIDE_NM."""
    rows = [(0.0, 0.0), (T_SLIDE, 0.0)]
    for k in range(1, 9):
        tau = T_RAMP * k / 8
        x = V_NM_PS * (tau ** 2 / (2 * T_RAMP) + (math.cos(2 * math.pi * tau / T_RAMP) - 1) * T_RAMP / (4 * math.pi ** 2))
        rows.append((T_SLIDE + tau, x))
    t_end = T_SLIDE + T_RAMP + (SLIDE_NM - rows[-1][1]) / V_NM_PS
    return rows + [(t_end, SLIDE_NM), (1000.0, SLIDE_NM)], t_end


def values(rows):
    return "".join(f"      {t:7.1f}  {v:.6f}\n" for t, v in rows)


def tip_top_conditions(rigid):
    """The tip top's loading: a rigid body (tip_body, rotation fixed: no rocking) or the node set, whose
    `prescribed force` is shared equally by its nodes (the tip may rock). y held, z loaded, x driven."""
    target, name = ("rigid body", "tip_body") if rigid else ("node set", "tip_top")
    blocks = [rigid_body("tip_body", "tip_top")] if rigid else []
    blocks += [fixed_displacement(name, "y"),  # a rigid body's node set holds the body's y
               prescribed("force", name, "z", "load", f"-{LOAD_NN} nN", target),
               prescribed("displacement", name, "x", "slide", target=target)]
    return "\n".join(blocks) + "\n"


def deck(rigid):
    name = "rigid_slide_rigid" if rigid else "rigid_slide_nodeset"
    slide, t_end = slide_rows()
    how = ("the tip top a rigid body (`begin rigid body`) loaded and driven at its reference point" if rigid else
           "the tip top loaded with `prescribed force` on its node set (equal shares per node), as before rigid bodies")
    return f"""# {name}.i -- written by make_decks.py (edit that, not this file).
# Force-controlled sliding of a silicon sphere (R = 27 nm) on a SAM-coated silicon flat (coating 1.6 nm,
# E = 8 GPa), junction model (W = 0.05 J/m^2, tau* = 194 MPa): {how}.
# 0 - 80 ps: normal load ramped to {LOAD_NN:g} nN (cycloidal); 120 - {t_end:.0f} ps: the tip top slides {SLIDE_NM:g} nm
# in +x at 10 m/s (cycloidal 40 ps speed ramp); y of the tip top held.
#
# Run:    build/bin/tribex run verification/rigid_slide/{name}.i -o {name}_output
# Check:  /usr/bin/python3 verification/rigid_slide/compare.py {name}_output  (README.md)
# END: the termination time. CI runs the rigid deck with --set "END=220 ps" (0.8 nm of slide, README.md
# "The CI run"): the rocking it guards against shows long before the 3 nm.
{{END = {t_end + 20:.1f} ps}}
begin sierra {name}
  begin function load
    type = piecewise linear
    abscissa unit = ps
    begin values
{values(load_rows())}    end values
  end function load
  begin function slide
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
{values(slide)}    end values
  end function slide
{elastic_material("silicon", 2330, 161, 0.23)}
{elastic_material("sam", 1000, 8, 0.4)}
{HEX8_FULLY_INTEGRATED}
  begin finite element model asperity
    begin generated asperity
      radius = 27 nm
      tip width = 24 nm
      tip height = 13 nm
      substrate width = 40 nm
      substrate depth = 20 nm
      element size = 0.8 nm
      fine half width = 9.6 nm
      fine depth = 3.2 nm
      grading ratio = 1.4
      coating thickness = 1.6 nm
      coating layers = 2
    end generated asperity
{block_parameters("tip", "silicon")}
{block_parameters("substrate", "silicon")}
{block_parameters("coating", "sam")}
  end finite element model asperity
  begin presto procedure load_and_slide
    begin time control
      termination time = {{END}}
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
{tip_top_conditions(rigid)}      begin contact definition tip_on_flat
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        contact axis = 0 0 0 0 0 1 nm
        begin interaction sphere_flat
          surfaces = flat tip     # the coating is the softer side: slave
          model = junction
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm
          junction strength = 194 MPa
          junction reference speed = 0.1 m/s
          junction gap tolerance = 0 nm
        end interaction sphere_flat
      end contact definition tip_on_flat
{history_output(2, "substrate_bottom", "tip_top tip_apex")}
{results_output(20, nodal_variables="displacement")}
    end presto region main
  end presto procedure load_and_slide
end sierra {name}
"""


if __name__ == "__main__":
    for rigid in (True, False):
        name = "rigid_slide_rigid" if rigid else "rigid_slide_nodeset"
        with open(os.path.join(HERE, name + ".i"), "w") as f:
            f.write(deck(rigid))
        print("wrote", name + ".i")
