# demo_hertz.i -- the W = 0 twin of demo.i (the deck `./tribex.sh demo` runs beside it): the same
# sphere, flat, mesh and driving with frictionless contact and no adhesion, so the two runs differ
# only in W (a quarter model, as demo.i). Run: build/bin/tribex run inputs/examples/demo_hertz.i -o demo_output/hertz
begin sierra demo_hertz
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0   0.00000
         10.0   0.00375
         20.0   0.01500
         30.0   0.03375
         40.0   0.06000
        140.0   0.36000
        150.0   0.36000
        315.0  -0.30000
    end values
  end function push

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon

  # Fully integrated: the concentrated penalty forces of node-to-face contact excite the hourglass
  # modes of one-point (mean-quadrature) elements at the surface; at these contact pressures
  # (p0 up to 14 GPa) that coupling pumped energy into the contact and inverted elements.
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8

  begin finite element model asperity
    begin generated asperity
      symmetry = quarter            # x, y >= 0: a quarter of the elements; forces and areas are 1/4
      radius = 27 nm
      tip width = 20 nm
      tip height = 12 nm
      substrate width = 60 nm
      substrate depth = 30 nm
      element size = 0.4 nm
      fine half width = 4 nm
      fine depth = 2 nm
      grading ratio = 1.4
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

  begin presto procedure indent
    begin time control
      termination time = 315 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
      quasi static = on             # run guards: kinetic energy below 5 % of internal energy while loaded
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = tip_top
        components = x y
      end fixed displacement
      begin fixed displacement      # the symmetry planes x = 0 and y = 0
        node set = symmetry_x
        components = x
      end fixed displacement
      begin fixed displacement
        node set = symmetry_y
        components = y
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
        contact axis = 0 0 0 0 0 1 nm
        begin interaction sphere_flat
          surfaces = tip flat
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 1.5 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
      begin results output fields
        time increment = 15 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra demo_hertz
