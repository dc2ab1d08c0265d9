# demo.i -- the deck `./tribex.sh demo` runs: a silicon sphere (R = 27 nm) pressed on a silicon flat
# with Lennard-Jones adhesion (W = 0.05 J/m^2, z0 = 0.3 nm: Tabor parameter 0.070, the DMT limit) to
# about 120 nN, held, then pulled off. Its twin demo_hertz.i is the same run without adhesion (W = 0).
# At these low loads the two separate: at zero load DMT's contact radius is 1.26 nm and Hertz's 0,
# and the adhesive tip holds on to -2 pi W R = -8.48 nN before it lets go (docs/theory.md 8.2).
#
# Run:    build/bin/tribex run inputs/examples/demo.i -o demo_output/dmt
#         build/bin/tribex run inputs/examples/demo_hertz.i -o demo_output/hertz
#         /usr/bin/python3 verification/dmt/compare.py demo_output/dmt --element-size 0.4 \
#             --hertz-output demo_output/hertz --plot demo_output/demo.png
# (`./tribex.sh demo` runs the two side by side, one per core, then the comparison and the plot.)
#
# The mesh is verification/dmt/dmt_coarse.i's generated asperity refined to 0.4 nm in a 4 nm fine
# region (the contact radius stays under 3.2 nm here, 8 elements), on a 60 x 60 x 30 nm substrate, as a
# quarter model (x, y >= 0, the planes x = 0 and y = 0 held in x resp. y: 7,529 hex8 instead of 30,116;
# history.csv holds a quarter of the forces and areas, which compare.py reads from log.txt and multiplies by 4);
# the tip top is pushed down 0.36 nm at 3 m/s (a 40 ps smooth start), held 10 ps, then pulled up at
# 4 m/s until the apex is 0.3 nm above contact, past pull-off (about +0.03 nm).
begin sierra demo
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
          model = adhesion
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm      # 20 z0: the law keeps 99 % of W (docs/theory.md 6.3)
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
end sierra demo
