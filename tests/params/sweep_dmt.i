# sweep_dmt.i -- the small DMT indentation of tests/parallel/mpi_dmt.i (R = 27 nm silicon sphere on a
# silicon flat, 1.6 nm elements, Lennard-Jones adhesion z0 = 0.3 nm, a 1.2 nm cycloidal push in 30 ps,
# then held to 40 ps) with its work of adhesion as a deck parameter, for the --set sweep of
# tests/params/ (sweep.py: W = 0, 0.05, 0.1 J/m^2 and the W = 0 run against model = frictionless).
# Not a verification case: the sweep checks that the adhesive force scales with W (DMT: 2 pi R W).
#
# Run:    build/bin/tribex run tests/params/sweep_dmt.i -o build/sweep_w006 --set W=0.06
{W = 0.05 J/m^2}     # work of adhesion (tribex run ... --set W=VALUE)
{R = 27 nm}          # sphere radius
begin sierra sweep_dmt
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.0  0.00000
           3.0  0.00774
           6.0  0.05836
           9.0  0.17836
          12.0  0.36774
          15.0  0.60000
          18.0  0.83226
          21.0  1.02164
          24.0  1.14164
          27.0  1.19226
          30.0  1.20000
         200.0  1.20000
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
      radius = {R}
      tip width = 32 nm
      tip height = 26 nm
      substrate width = 60 nm
      substrate depth = 30 nm
      element size = 1.6 nm
      fine half width = 6.4 nm
      fine depth = 3.2 nm
      grading ratio = 1.35
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
      termination time = 40 ps
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
      begin contact definition tip_on_flat
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        contact axis = 0 0 0 0 0 1 nm
        begin interaction sphere_flat
          surfaces = tip flat
          model = adhesion
          work of adhesion = {W}
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm      # 20 z0: the law keeps 99 % of W (docs/theory.md 6.3)
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 1 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
    end presto region main
  end presto procedure indent
end sierra sweep_dmt
