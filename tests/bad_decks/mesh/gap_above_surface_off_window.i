# expect: 30: footprint lies outside the AFM surface's window
# gap above surface with the tip's apex x y off the AFM window: exit 2 at set-up (tribex check), naming the asperity block
begin sierra tip_gap
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin solid section hex8
    formulation = mean_quadrature
  end solid section hex8
  begin finite element model m
    begin afm surface
      file = ../../../inputs/data/afm/di-3.di
      window = 110 160 20 20 nm
      small window = interpolate   # di-3 has 39 nm pixels: the window is the spline between them
      element size = 2 nm
      depth = 10 nm
    end afm surface
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin generated asperity
      substrate = none
      radius = 50 nm
      tip width = 10 nm
      tip height = 6 nm
      element size = 2 nm
      apex position = 400 400 0 nm     # far from the 110-130 x 160-180 nm window
      gap above surface = 0.5 nm
    end generated asperity
  end finite element model m
  begin presto procedure p
    begin time control
      termination time = 1 ps
    end time control
    begin presto region r
      use finite element model m
      begin contact definition tip_on_surface
        contact surface tip contains tip_surface
        contact surface surface contains substrate_top
        begin interaction frictionless
          surfaces = tip surface
          model = frictionless
        end interaction frictionless
      end contact definition tip_on_surface
    end presto region r
  end presto procedure p
end sierra tip_gap
