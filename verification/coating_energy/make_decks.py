#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the decks of the soft-coating energy study (verification/coating_energy/README.md).

A silicon sphere pressed 1 nm into a SAM-like coating bonded on silicon and withdrawn, with the
default node-to-face penalty enforcement: the energy balance must hold within 0.5 % over the whole
run for every variant (issue 22: before the fix the contact injected up to 10 %). `base.i` is the
deck of the issue as a user wrote it (R = 20 nm, 1 nm elements, 2 nm coating in 6 layers); the
variants are a coarser model (R = 10 nm) that changes one thing at a time: coating layers (elements
through the coating), coating modulus E_c, work of adhesion W, drive speed, element formulation.

usage: make_decks.py   (rewrites decks/*.i beside this script)
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))

DECK = """# {title}
# Written by verification/coating_energy/make_decks.py; checked by compare.py (max |energy_error| <= 0.5 %).
# Drive: push {depth} nm at {speed} m/s, hold 10 ps, withdraw to {pull} nm above the start by {t3:g} ps.
begin sierra {name}
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0 0
      {t1:g} {depth}
      {t2:g} {depth}
      {t3:g} -{pull}
    end values
  end function push
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin property specification for material sam
    density = 1000 kg/m^3
    begin parameters for model elastic
      youngs modulus = {ec} GPa
      poissons ratio = 0.4
    end parameters for model elastic
  end property specification for material sam
  begin solid section hex8
    formulation = {formulation}
  end solid section hex8
  begin finite element model asperity
    begin generated asperity
      radius = {radius} nm
      tip width = {tip_width} nm
      tip height = {tip_height} nm
      substrate width = {substrate_width} nm
      substrate depth = {substrate_depth} nm
      element size = 1 nm
      coating thickness = 2 nm{layers_line}
    end generated asperity
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
    begin parameters for block coating
      material = sam
      section = hex8
    end parameters for block coating
  end finite element model asperity
  begin presto procedure indent
    begin time control
      termination time = {t3:g} ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = tip_top
        components = x y
      end fixed displacement
      begin prescribed displacement
        node set = tip_top
        component = z
        function = push
        scale factor = -1
      end prescribed displacement
      begin contact definition tip_on_sam
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        begin interaction sphere_flat
          surfaces = tip flat
          model = {model}{adhesion_lines}
        end interaction sphere_flat
      end contact definition tip_on_sam
      begin history output hist
        time increment = 5 ps
        reaction force = tip_top
      end history output hist
    end presto region main
  end presto procedure indent
end sierra {name}
"""

# name: (title, overrides)
BASE = dict(radius=10, tip_width=12, tip_height=10, substrate_width=32, substrate_depth=16, layers=2, ec=8,
            w=0.1, speed=5, formulation="fully_integrated", depth=1.0, pull=0.8)
VARIANTS = {
    "base": ("the issue's deck: R = 20 nm, 2 nm coating in the default 6 layers, E_c 8 GPa, W 0.1 J/m^2, 5 m/s",
             dict(radius=20, tip_width=24, tip_height=20, substrate_width=80, substrate_depth=40, layers=None,
                  end=500.0)),
    "layers1": ("coating in 1 element (2 nm thick)", dict(layers=1)),
    "layers2": ("coating in 2 elements (the coarse reference variant)", dict()),
    "layers4": ("coating in 4 elements", dict(layers=4)),
    "ec2": ("E_c = 2 GPa", dict(ec=2)),
    "ec16": ("E_c = 16 GPa", dict(ec=16)),
    "w0": ("W = 0 (frictionless)", dict(w=0)),
    "speed1": ("drive 1 m/s (0.5 nm push)", dict(speed=1, depth=0.5, pull=0.4)),
    "speed10": ("drive 10 m/s", dict(speed=10)),
    "mean_quadrature": ("mean-quadrature elements with hourglass control", dict(formulation="mean_quadrature")),
    "worst": ("1 layer, E_c 2 GPa, 10 m/s, mean quadrature", dict(layers=1, ec=2, speed=10, formulation="mean_quadrature")),
}


def deck(name, title, p):
    t1 = p["depth"] / p["speed"] * 1000.0  # nm / (m/s) = ns -> ps
    t2 = t1 + 10.0
    t3 = p.get("end") or t2 + (p["depth"] + p["pull"]) / p["speed"] * 1000.0
    adhesion = ("\n          work of adhesion = %g J/m^2\n          equilibrium separation = 0.3 nm" % p["w"]) if p["w"] > 0 else ""
    return DECK.format(title=f"Soft-coating energy study, {name}: {title}.", name=f"coating_energy_{name}",
                       depth=p["depth"], pull=p["pull"], speed=p["speed"], t1=t1, t2=t2, t3=t3, ec=p["ec"],
                       formulation=p["formulation"], radius=p["radius"], tip_width=p["tip_width"],
                       tip_height=p["tip_height"], substrate_width=p["substrate_width"],
                       substrate_depth=p["substrate_depth"],
                       layers_line="" if p["layers"] is None else "\n      coating layers = %d" % p["layers"],
                       model="adhesion" if p["w"] > 0 else "frictionless", adhesion_lines=adhesion)


def main():
    out = os.path.join(HERE, "decks")
    os.makedirs(out, exist_ok=True)
    for name, (title, over) in VARIANTS.items():
        p = dict(BASE, **over)
        with open(os.path.join(out, name + ".i"), "w") as f:
            f.write(deck(name, title, p))
    print(f"wrote {len(VARIANTS)} decks to {out}")


if __name__ == "__main__":
    main()
