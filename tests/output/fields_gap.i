# fields_gap.i -- the `gap` and `contact_pressure` result fields of two blocks set 1 nm apart, with
# Lennard-Jones adhesion across the gap (tests/output/check_fields_gap.py; docs/theory.md 6.1, 12.1).
#
#        +-------------+   block `upper`: 10 x 10 x 5 nm, 3 x 3 x 2 hex8, origin z = 6 nm
#          1 nm gap        upper_zmin (slave, one pass) over lower_zmax (master)
#        +-------------+   block `lower`: 10 x 10 x 5 nm, 4 x 4 x 2 hex8
#   Both blocks held at their far faces (upper_zmax and lower_zmin fixed). At t = 0 every slave node
#   projects on the master face below it with gap = 1 nm, no node is in contact, the adhesion pulls
#   with the traction sigma_s(g + z0) = sigma_LJ(1.5 nm) - sigma_LJ(h_c = 20 z0) (W = 0.05 J/m^2,
#   z0 = 0.5 nm), so contact_pressure = -9.8e6 Pa (tensile: negative) on the slave nodes, 0 elsewhere;
#   the master's nodes have no gap (NaN).
begin sierra fields_gap
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin solid section hex8
  end solid section hex8
  begin finite element model blocks
    begin generated box lower
      size = 10 10 5 nm
      intervals = 4 4 2
    end generated box lower
    begin generated box upper
      origin = 0 0 6 nm
      size = 10 10 5 nm
      intervals = 3 3 2
    end generated box upper
    begin parameters for block lower
      material = silicon
      section = hex8
    end parameters for block lower
    begin parameters for block upper
      material = silicon
      section = hex8
    end parameters for block upper
  end finite element model blocks
  begin presto procedure hold
    begin time control
      termination time = 0.25 ps
    end time control
    begin presto region main
      use finite element model blocks
      energy error warning = 0.05  # the first steps of the released attraction: 1.42 % at step 1 (energies 1e-22 J); the fields are checked at t = 0
      begin fixed displacement
        node set = lower_zmin
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = upper_zmax
        components = x y z
      end fixed displacement
      begin contact definition interface
        contact surface upper_face contains upper_zmin
        contact surface lower_face contains lower_zmax
        begin interaction apart
          surfaces = upper_face lower_face
          model = adhesion
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.5 nm
        end interaction apart
      end contact definition interface
      begin history output hist
        step increment = 10
      end history output hist
      begin results output fields
        time increment = 0.25 ps
        nodal variables = contact_status contact_pressure gap
        element variables = von_mises
        length unit = nm
        format = both
      end results output fields
    end presto region main
  end presto procedure hold
end sierra fields_gap
