#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Writes the AFM sliding decks (the report's Section 3.5, Fig. 3.9) from one template: a silicon
sphere (R = 50 nm) pressed with 500 nN into a track on the di-3 AFM scan (10 um polysilicon scan, as
in the report), then slid along the track (+y) at 7.5 m/s.
Cases: (a) silicon on silicon; (b) silicon on a 2 nm SAM layer (E = 8 GPa, nu = 0.4, tau* = 194 MPa).
Variants: reduced (CI: 1 nm elements, 40 x 36 nm window, 3 nm of sliding) and full (0.5 nm elements,
100 x 100 nm window with the 35 x 100 nm track, 70 nm of sliding). Run it after editing the template:

    /usr/bin/python3 inputs/examples/afm_sliding/make_decks.py

The load and the sliding use cycloidal ramps (zero acceleration jump at both ends) written as
piecewise-linear tables at 5 ps over the ramps; the tables and the deck blocks come from
tools/python/deck_templates.py (shared with the other make_decks.py).
"""
import argparse
import math
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[3] / "tools" / "python"))
from deck_templates import (HEX8_FULLY_INTEGRATED, NM, PS, block_parameters, elastic_material,  # noqa: E402
                            contact_definition, fixed_displacement, function_table, history_output, piecewise_linear_function,
                            prescribed, ramped_travel, results_output, rigid_body, table_times, write_deck)

# Mixed blocks (issue 24): only SKIN_LAYERS element layers under the contact surfaces are fully
# integrated (`begin surface layer block`, mesh/README.md); below them one-point elements. One layer
# keeps verification/hertz and verification/dmt within their tolerances (their READMEs); here two:
# with one, the reduced runs' friction read 0.89 % (a) and 1.06 % (b) above the fully integrated
# decks', with two 0.45 % and 0.46 % (docs/measurements/2026-11-25-afm-sliding-mixed-blocks.md, "Mixed blocks").
SKIN_LAYERS = 2
MIXED_NOTE = """\
  # Fully integrated at GPa contact pressures (verification/hertz/README.md): the skin blocks under
  # the contact surfaces (tip_skin, and substrate_skin or coating_skin); mean quadrature elsewhere."""
# --fully-integrated: the reference the mixed decks are measured against
# (docs/measurements/2026-11-25-afm-sliding-mixed-blocks.md "Mixed blocks").
FULLY_INTEGRATED_NOTE = """\
  # Fully integrated everywhere: the reference deck (make_decks.py --fully-integrated) against which
  # the mixed-block decks (fully integrated skins, mean quadrature below) are checked."""
HEX8_MEAN_QUADRATURE = """\
  begin solid section hex8_mq
    formulation = mean_quadrature
  end solid section hex8_mq"""


def surface_layer_block(name, block, surface, layers):
    """A `begin surface layer block` (inside `begin finite element model`)."""
    return (f"    begin surface layer block {name}\n      from block = {block}\n      surface = {surface}\n"
            f"      layers = {layers}\n    end surface layer block {name}")


RAMP = 40 * PS        # sliding speed ramp
LOAD_RAMP = 80 * PS   # 0 -> 500 nN
HOLD = 60 * PS        # settle at 500 nN before sliding (--hold: the mass-scaled decks' heavier tip needs longer)
SPEED = 7.5           # m/s
LOAD = 500            # nN


# Parallel runs (full variant): the tip slides 70 nm along y, so the partition's cuts go along y
# (recursive coordinate bisection, y's sides scaled by 0.01: no cut crosses the track) and the contact
# zone stays shared by the ranks all the way; METIS's cut at y = 150 nm put it on one rank at a time
# (docs/measurements/2026-11-27-afm-sliding-mass-scaling-8.md "Decomposition along the slide"). A serial
# run ignores the block.
DECOMPOSITION_ALONG_SLIDE = """
      begin decomposition
        method = rcb
        coordinate scale = 1 0.01 1
      end decomposition"""

RESTART_EVERY_10_MIN = """
      begin restart output
        wall time increment = 600 s
      end restart output"""


def load_fraction(t):
    """0 -> 1 over LOAD_RAMP, (1 - cos) / 2: no jump in the load rate at either end."""
    return 1.0 if t >= LOAD_RAMP else 0.5 * (1 - math.cos(math.pi * t / LOAD_RAMP))


# Tip start (x, y) on the map and the apex height there: the apex z at which the sphere first touches
# the spline surface (found on `tribex mesh afm inputs/data/afm/di-3.di --window 100nm,100nm,
# 100nm,100nm --element-size 2nm`, max over the footprint of s(x, y) - (R - sqrt(R^2 - r^2)))
# plus 0.3 nm (z0): the tip starts just out of contact and the load brings it down.
VARIANTS = {
    "reduced": dict(window="102 153 40 36", track="106 156 28 30", h=1.0, depth=15, start=(120, 170),
                    touch=37.6126, distance=3.0, tip_width=26, tip_height=8, fine_half_width=11,
                    tip_fine_depth=2, coating_layers=3, hist=2, fields=100, restart="", decomposition=""),
    "full": dict(window="100 100 100 100", track="102.5 100 35 100", h=0.5, depth=40, start=(120, 115),
                 touch=34.3498, distance=70.0, tip_width=30, tip_height=12, fine_half_width=13,
                 tip_fine_depth=3, coating_layers=6, hist=5, fields=1000,
                 # hours long: a restart file every 10 min of wall time (--restart OUT/restart.h5 resumes)
                 restart=RESTART_EVERY_10_MIN, decomposition=DECOMPOSITION_ALONG_SLIDE),
}
CASES = {
    "a_si": dict(title="(a) silicon on silicon", coating=False, tau=195,
                 tau_note="tau* = 195 MPa (Si on Si, as verification/sphere_sliding)"),
    "b_sam": dict(title="(b) silicon on a 2 nm SAM layer", coating=True, tau=194,
                  tau_note="tau* = 194 MPa (Si on CH3-thiol SAM, the report's Section 3.5)"),
}

TEMPLATE = """\
# {name}.i -- written by make_decks.py (edit that, not this file).
# AFM sliding example {title}, {variant} variant (the report's Section 3.5, Fig. 3.9): a silicon sphere
# (R = 50 nm, a {tip_width} nm wide die) pressed with {load} nN into the di-3 AFM surface (10 um polysilicon
# scan, levelled, bicubic spline) and slid {distance:g} nm along the track (+y) at {speed} m/s.
# Junction model: W = 0.05 J/m^2, z0 = 0.3 nm, cutoff 6 nm, {tau_note}.
#
# Run:    build/bin/tribex run inputs/examples/afm_sliding/{name}.i -o {name}_output
# Plot:   /usr/bin/python3 inputs/examples/afm_sliding/afm_sliding.py {name}_output ...  (see README.md)
#
# Time line: 0 - {t_load:.0f} ps load ramp to {load} nN (load control on z of tip_body, the tip top as a rigid
# body; the tip starts 0.3 nm above first touch), {t_load:.0f} - {t_slide:.0f} ps hold, then tip_body
# moves in +y at {speed} m/s (cycloidal 40 ps ramp) to {t_end:.0f} ps; its x is fixed.
# Substrate: bottom fixed (it carries the {load} nN; a dashpot alone cannot hold a static load), silent
# boundaries on the four sides (absorb the waves of the load and the sliding).
# Quasi-static: mass damping 5e11 1/s (about half critical for the tip bouncing on the contact
# stiffness); the check is kinetic / internal energy at the end of the hold (afm_sliding.py).
# END: the termination time; CI stops the reduced decks at 1.5 nm of sliding (afm_sliding.py --set, README.md).
{{END = {t_end:.1f} ps}}
begin sierra {name}
{load_function}
{slide_function}

{silicon}
{sam_material}
{element_note}
{hex8}{hex8_mq}

  begin finite element model afm_track
    begin afm surface
      file = ../../data/afm/di-3.di
      channel = 0
      window = {window} nm
      small window = interpolate   # di-3 has 39 nm pixels: the window is the spline between them
      track = {track} nm
      element size = {h} nm
      depth = {depth} nm{coating}
      grading ratio = 1.3
    end afm surface
    begin generated asperity
      substrate = none
      radius = 50 nm
      tip width = {tip_width} nm
      tip height = {tip_height} nm
      element size = {h} nm
      fine half width = {fine_half_width} nm
      fine depth = {tip_fine_depth} nm
      grading ratio = 1.3
      apex position = {x0} {y0} {apex_z:.4f} nm
    end generated asperity
{blocks}
  end finite element model afm_track

  begin presto procedure press_and_slide
    begin time control
      termination time = {{END}}
    end time control
    begin presto region main
      use finite element model afm_track
      mass damping coefficient = 5e11 1/s{decomposition}
{substrate_bottom}
      begin silent boundary
        side set = substrate_sides
      end silent boundary
{tip_top}
{contact}
{outputs}
    end presto region main
  end presto procedure press_and_slide
end sierra {name}
"""

# Junction model on the tip-track pair ({tau}: tau* in MPa, per case).
JUNCTION = """\
          model = junction
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm
          junction strength = {tau} MPa
          junction reference speed = 0.1 m/s   # backward Euler: tanh(V/v_ref) = 1 in sliding
          junction gap tolerance = 0 nm
"""

SAM = """
  # CH3-thiol SAM (the report's Section 3.5: E = 8 GPa, nu = 0.4); density of an alkanethiol
  # monolayer, about 1000 kg/m^3 (not given in the report; it only sets the coating's wave speed).
""" + elastic_material("sam", 1000, 8, 0.4) + "\n"


# `--mass-scaling F` (issue 24): the same decks with selective mass scaling to F x the unscaled step,
# written beside them as afm_sliding_<variant>_<case>_mass_scaled.i (afm_sliding.py --mass-scaled runs them).
# Kept in the repository: all four at F = 8 with a 900 ps hold
# (docs/measurements/2026-11-27-afm-sliding-mass-scaling-8.md "Mass scaling 8"):
# `--mass-scaling 8 --mass-limit 22 --hold 900` (2,090 % added on the full decks, about 3,300 % on the
# uniform 1 nm reduced mesh: `--mass-limit 35 --variant reduced`). The quasi-static slide does not feel the
# inertia (friction and contact radius within 0.05 % of the factor-5 runs, 0.07 % of the unscaled reduced
# runs); the hold does: the heavier tip settles more slowly (at F = 4 it had not in the 60 ps hold: reduced
# (a) P +5.9 %), hence the longer hold. The default 5 % guard would refuse these decks, so they raise it
# knowingly.
MASS_SCALING = """
      begin mass scaling
        largest factor = {factor:g}                  # target time step = {factor:g} x the unscaled step
        maximum added mass fraction = {limit:g}
      end mass scaling"""


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--mass-scaling", type=float, metavar="F",
                    help="write the *_mass_scaled.i variants: selective mass scaling to F x the unscaled step")
    ap.add_argument("--mass-limit", type=float, default=0.05, help="their 'maximum added mass fraction'")
    ap.add_argument("--hold", type=float, default=HOLD / PS, metavar="PS",
                    help="the hold at the full load before sliding, ps (default %(default)g; afm_sliding.py reads it "
                         "from the deck's time line)")
    ap.add_argument("--fully-integrated", action="store_true",
                    help="write the *_fully_integrated.i reference decks: every block fully integrated, no skins")
    ap.add_argument("--variant", choices=list(VARIANTS), help="write this variant's decks only")
    ap.add_argument("--case", choices=list(CASES), help="write this case's decks only")
    a = ap.parse_args()
    if not a.hold >= 20:
        ap.error(f"--hold {a.hold:g}: the hold must be at least 20 ps (afm_sliding.py checks the load over its last 20 ps)")
    here = pathlib.Path(__file__).resolve().parent
    for vname, v in VARIANTS.items():
        for cname, c in CASES.items():
            if a.variant not in (None, vname) or a.case not in (None, cname):
                continue
            name = (f"afm_sliding_{vname}_{cname}" + ("_fully_integrated" if a.fully_integrated else "")
                    + ("_mass_scaled" if a.mass_scaling else ""))
            t_slide = LOAD_RAMP + a.hold * PS
            t_end = t_slide + (v["distance"] * NM + SPEED * RAMP / 2) / SPEED
            # The contact surface of the track is substrate_top: the coating's top when there is one.
            track_block = "coating" if c["coating"] else "substrate"
            if a.fully_integrated:
                blocks = [block_parameters("tip", "silicon"), block_parameters("substrate", "silicon")]
                if c["coating"]:
                    blocks.append(block_parameters("coating", "sam"))
            else:
                blocks = [surface_layer_block("tip_skin", "tip", "tip_surface", SKIN_LAYERS),
                          surface_layer_block(f"{track_block}_skin", track_block, "substrate_top", SKIN_LAYERS),
                          block_parameters("tip", "silicon", "hex8_mq"), block_parameters("tip_skin", "silicon"),
                          block_parameters("substrate", "silicon", "hex8_mq")]
                if c["coating"]:
                    blocks.append(block_parameters("coating", "sam", "hex8_mq"))
                blocks.append(block_parameters(f"{track_block}_skin", "sam" if c["coating"] else "silicon"))
            load_table = function_table(load_fraction, table_times(t_end, 0.0, LOAD_RAMP), "8.1f", scale=1.0)
            slide_table = function_table(lambda t: ramped_travel(t, SPEED, t_slide, ramp=RAMP),
                                         table_times(t_end, t_slide, t_slide + RAMP), "8.1f")
            text = TEMPLATE.format(
                name=name, title=c["title"], variant=vname, tip_width=v["tip_width"], load=LOAD,
                distance=v["distance"], speed=SPEED, tau_note=c["tau_note"], t_load=LOAD_RAMP / PS,
                t_slide=t_slide / PS, t_end=t_end / PS,
                load_function=piecewise_linear_function("load", load_table, ordinate_unit=None),
                slide_function=piecewise_linear_function("slide", slide_table),
                silicon=elastic_material("silicon", 2330, 161, 0.23), hex8=HEX8_FULLY_INTEGRATED,
                hex8_mq="" if a.fully_integrated else "\n" + HEX8_MEAN_QUADRATURE,
                element_note=FULLY_INTEGRATED_NOTE if a.fully_integrated else MIXED_NOTE,
                sam_material=SAM if c["coating"] else "",
                window=v["window"], track=v["track"], h=v["h"], depth=v["depth"],
                coating=(f"\n      coating thickness = 2 nm\n      coating layers = {v['coating_layers']}"
                         if c["coating"] else ""),
                tip_height=v["tip_height"], fine_half_width=v["fine_half_width"],
                tip_fine_depth=v["tip_fine_depth"], x0=v["start"][0], y0=v["start"][1],
                apex_z=v["touch"] + 0.3, blocks="\n".join(blocks),
                decomposition=v["decomposition"], substrate_bottom=fixed_displacement("substrate_bottom", "x y z"),
                # The tip top is a rigid body (issue 56): with the force shared equally by its nodes the
                # tip rocked (verification/rigid_slide); its x held through the body's node set.
                tip_top="\n".join([rigid_body("tip_body", "tip_top"), fixed_displacement("tip_body", "x"),
                                   prescribed("force", "tip_body", "z", "load", f"-{LOAD} nN", "rigid body"),
                                   prescribed("displacement", "tip_body", "y", "slide", target="rigid body")]),
                outputs=history_output(v["hist"], "substrate_bottom", "tip_top tip_apex") + "\n" + results_output(v["fields"])
                + v["restart"],
                contact=contact_definition("tip_on_track", [("tip", "tip_surface"), ("track", "substrate_top")],
                                           f"{v['start'][0]} {v['start'][1]} 0 0 0 1", "junction",
                                           JUNCTION.format(tau=c["tau"])))
            if a.mass_scaling:
                damping = "      mass damping coefficient = 5e11 1/s"
                text = text.replace(damping, damping + MASS_SCALING.format(factor=a.mass_scaling, limit=a.mass_limit), 1)
            write_deck(here, name, text)
            print("wrote", name + ".i")


if __name__ == "__main__":
    main()
