# Seed with the contact part of the schema (issue 29, item 5): two boxes, a contact definition with its
# options and one interaction of each model and enforcement, the run-guard keys of the region.
begin sierra contact_seed
  begin property specification for material steel
    density = 7850
    begin parameters for model elastic
      youngs modulus = 200e9
      poissons ratio = 0.3
    end
  end
  begin solid section sec
    formulation = fully_integrated
  end
  begin finite element model m
    begin generated box lower
      size = 4 4 1 nm
      intervals = 2 2 1
    end
    begin generated box upper
      origin = 0 0 1 nm
      size = 4 4 1 nm
      intervals = 3 3 1
    end
    begin parameters for block lower
      material = steel
      section = sec
    end
    begin parameters for block upper
      material = steel
      section = sec
    end
  end
  begin presto procedure p
    begin time control
      termination time = 1 ps
    end
    begin presto region r
      use finite element model = m
      energy error warning = 0.02
      energy error limit = 0.2
      penetration warning = 0.3
      quasi static = on
      kinetic energy warning = 0.1
      contact motion warning = 0.4
      contact motion limit = 2
      begin contact definition c
        penalty scale factor = 0.5
        search margin = 6 nm
        contact surface top contains lower_zmax
        contact surface bottom contains upper_zmin
        contact surface side contains upper_xmin
        begin interaction stick
          surfaces = bottom top
          model = junction
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm
          junction strength = 195 MPa
          junction reference speed = 0.1 m/s
          junction gap tolerance = 0 nm
          symmetric = on
        end
        begin interaction mortar
          surfaces = side top
          enforcement = mortar
          model = adhesion
          work of adhesion = 0.1 J/m^2
          equilibrium separation = 0.3 nm
        end
      end
      begin history output h
        step increment = 1
        reaction force = lower_zmin
      end
    end
  end
end
