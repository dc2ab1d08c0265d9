# Soft-coating energy study, speed1: drive 1 m/s (0.5 nm push).
# Written by verification/coating_energy/make_decks.py; checked by compare.py (max |energy_error| <= 0.5 %).
# Drive: push 0.5 nm at 1 m/s, hold 10 ps, withdraw to 0.4 nm above the start by 1410 ps.
# END: the termination time; CI stops the coarse decks 20-35 ps after the last contact (README.md).
{END = 1410 ps}
begin sierra coating_energy_speed1
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0  0.00000
      500  0.50000
      510  0.50000
      1410  -0.40000
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
      youngs modulus = 8 GPa
      poissons ratio = 0.4
    end parameters for model elastic
  end property specification for material sam
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8
  begin finite element model asperity
    begin generated asperity
      radius = 10 nm
      tip width = 12 nm
      tip height = 10 nm
      substrate width = 32 nm
      substrate depth = 16 nm
      element size = 1 nm
      coating thickness = 2 nm
      coating layers = 2
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
      termination time = {END}
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
          model = adhesion
          work of adhesion = 0.1 J/m^2
          equilibrium separation = 0.3 nm
        end interaction sphere_flat
      end contact definition tip_on_sam
      begin history output hist
        time increment = 5 ps
        reaction force = tip_top
      end history output hist
    end presto region main
  end presto procedure indent
end sierra coating_energy_speed1
