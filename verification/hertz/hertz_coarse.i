# hertz_coarse.i -- Hertz contact of a silicon sphere (R = 27 nm) on a silicon flat, frictionless,
# no adhesion: the coarse variant that CI runs (verification/hertz/README.md).
#
# Run:    build/bin/tribex run verification/hertz/hertz_coarse.i -o hertz_coarse_output
# Check:  /usr/bin/python3 verification/hertz/compare.py hertz_coarse_output --tolerance 0.03
#
#             tip_top: pushed down 2.4 nm in 300 ps (cycloidal ramp: zero speed at both ends), x and y held
#          +-----------+
#          |    tip    |   32 nm square column, spherical bottom face tip_surface (R = 27 nm)
#           \_________/
#   +---------------------------+ substrate_top (master surface)
#   |         substrate         |  120 nm wide, 60 nm deep, graded from 0.6 nm at the contact
#   +---------------------------+ substrate_bottom: fixed
#
# What it shows: penalty contact between two deformable bodies (tip_surface -> substrate_top),
# the generated asperity mesh, contact area/radius/force histories and the gap field used to
# measure the contact radius between nodes (compare.py), quasi-static driving (KE << IE is
# checked by compare.py).
begin sierra hertz_coarse
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0  0.00000
         10.0  0.00058
         20.0  0.00464
         30.0  0.01548
         40.0  0.03614
         50.0  0.06920
         60.0  0.11672
         70.0  0.18012
         80.0  0.26012
         90.0  0.35672
        100.0  0.46920
        110.0  0.59614
        120.0  0.73548
        130.0  0.88464
        140.0  1.04058
        150.0  1.20000
        160.0  1.35942
        170.0  1.51536
        180.0  1.66452
        190.0  1.80386
        200.0  1.93080
        210.0  2.04328
        220.0  2.13988
        230.0  2.21988
        240.0  2.28328
        250.0  2.33080
        260.0  2.36386
        270.0  2.38452
        280.0  2.39536
        290.0  2.39942
        300.0  2.40000
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
      radius = 27 nm
      tip width = 32 nm
      tip height = 26 nm
      substrate width = 120 nm
      substrate depth = 60 nm
      element size = 0.6 nm
      fine half width = 6.6 nm
      fine depth = 2.4 nm
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
      termination time = 330 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 2e10 1/s
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
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 3 ps
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
end sierra hertz_coarse
