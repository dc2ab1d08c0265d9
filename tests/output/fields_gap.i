# fields_gap.i -- the `gap` and `contact_pressure` result fields of two blocks set 1 nm apart
# (tests/output/check_fields_gap.py; docs/theory.md 12.1).
#
#        +-------------+   block `upper`: 10 x 10 x 5 nm, 3 x 3 x 2 hex8, origin z = 6 nm
#          1 nm gap        upper_zmin (slave, one pass) over lower_zmax (master)
#        +-------------+   block `lower`: 10 x 10 x 5 nm, 4 x 4 x 2 hex8
#   Both blocks held (upper_zmax and lower_zmin fixed) and nothing loaded: every slave node projects
#   on the master face below it with gap = 1 nm (within the search margin, the master's mean face
#   edge of 2.5 nm), no node is in contact (pressure 0), and the master's nodes have no gap (NaN).
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
      termination time = 2 ps
    end time control
    begin presto region main
      use finite element model blocks
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
        end interaction apart
      end contact definition interface
      begin history output hist
        step increment = 10
      end history output hist
      begin results output fields
        time increment = 1 ps
        nodal variables = contact_status contact_pressure gap
        element variables = von_mises
        length unit = nm
        format = both
      end results output fields
    end presto region main
  end presto procedure hold
end sierra fields_gap
