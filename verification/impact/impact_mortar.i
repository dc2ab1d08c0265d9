# impact_mortar.i -- impact.i with `enforcement = mortar` (segment-to-segment contact, contact/mortar/):
# the same checks (energy 1 %, momentum to round-off) for the mortar enforcement.
#
# Run:    build/bin/tribex run verification/impact/impact_mortar.i -o impact_mortar_output
# Check:  /usr/bin/python3 verification/impact/compare.py impact_mortar_output/history.csv
#
#          +------+   block `top`: 6 x 6 x 6 nm, 5 x 5 x 5 hex8, v = -200 m/s in z,
#          |      |   starts 0.3 nm above the lower block
#          +------+
#   +------------------+   block `bottom`: 12 x 12 x 6 nm, 8 x 8 x 4 hex8 (non-matching faces)
#   +------------------+   free: nothing is fixed, so total momentum must be conserved exactly
#
# What it shows: the penalty contact conserves momentum to round-off (equal and opposite forces
# distributed with the face shape functions) and, with no bulk or hourglass viscosity, the total
# energy through impact and rebound (compare.py: within 1 %); the contact work column returns to
# zero once the blocks separate.
begin sierra impact
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin solid section undamped
    linear bulk viscosity = 0
    quadratic bulk viscosity = 0
  end solid section undamped
  begin finite element model blocks
    begin generated box bottom
      origin = -6 -6 -6 nm
      size = 12 12 6 nm
      intervals = 8 8 4
    end generated box bottom
    begin generated box top
      origin = -3 -3 0.3 nm
      size = 6 6 6 nm
      intervals = 5 5 5
    end generated box top
    begin parameters for block bottom
      material = silicon
      section = undamped
    end parameters for block bottom
    begin parameters for block top
      material = silicon
      section = undamped
    end parameters for block top
  end finite element model blocks
  begin presto procedure drop
    begin time control
      termination time = 40 ps
    end time control
    begin presto region main
      use finite element model blocks
      begin initial velocity
        block = top
        velocity = 0 0 -200 m/s
      end initial velocity
      begin contact definition drop
        contact surface falling contains top_zmin
        contact surface ground contains bottom_zmax
        begin interaction impact
          surfaces = falling ground
          enforcement = mortar
        end interaction impact
      end contact definition drop
      begin history output hist
        step increment = 20
        mean displacement = top_all bottom_all
      end history output hist
    end presto region main
  end presto procedure drop
end sierra impact
