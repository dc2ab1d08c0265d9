# A configuration made to inject energy (issue 22): node-to-face penalty contact on one-point
# (mean_quadrature) elements, the tip pushed 4 nm into the flat at 40 m/s. The penalty point forces feed
# the surface hourglass modes: contact_work turns negative, the penetration grows past 0.2 element sizes,
# the surface nodes start to jump, the energy balance breaks, and the run stops at the contact motion
# limit (exit 3). Warnings expected: unsafe_choice (set-up), penetration, contact_motion, energy_error.
# With 'energy error limit = 0.004' added (tests/guards/CMakeLists.txt) it stops at that limit instead.
begin sierra inject
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0 0
      100 4
    end values
  end function push
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
  begin finite element model asperity
    begin generated asperity
      radius = 10 nm
      tip width = 12 nm
      tip height = 10 nm
      substrate width = 24 nm
      substrate depth = 8 nm
      element size = 2 nm
    end generated asperity
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
  end finite element model asperity
  begin presto procedure throw
    begin time control
      termination time = 100 ps

    end time control
    begin presto region main
      use finite element model asperity
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
      begin contact definition tip_on_flat

        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        begin interaction sphere_flat
          surfaces = tip flat
          model = frictionless
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        step increment = 1
      end history output hist
    end presto region main
  end presto procedure throw
end sierra inject
