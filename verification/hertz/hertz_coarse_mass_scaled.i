# hertz_coarse_mass_scaled.i -- hertz_coarse.i with selective mass scaling
# (begin mass scaling, docs/theory.md 1.4.1): every element whose stable step is below twice the
# smallest gets its density raised to reach it. Otherwise the deck is hertz_coarse.i line for line (same mesh,
# driving, outputs); the compare script checks it with the unscaled deck's tolerance (verification/hertz/README.md, "Mass scaling").
#
# hertz_coarse.i -- Hertz contact of a silicon sphere (R = 27 nm) on a silicon flat, frictionless,
# no adhesion: the coarse variant that CI runs (verification/hertz/README.md).
#
# Run:    build/bin/tribex run verification/hertz/hertz_coarse_mass_scaled.i -o hertz_coarse_mass_scaled_output
# Check:  /usr/bin/python3 verification/hertz/compare.py hertz_coarse_mass_scaled_output --element-size 0.8 --tolerance 0.03
# Quarter model (`symmetry = quarter`: x, y >= 0, the planes x = 0 and y = 0 held in x resp. y) with
# the mesh resolution, boundary conditions and driving of the full model it replaced (a quarter of its
# elements): forces, areas and energies in history.csv are a quarter of the full problem's; the compare
# scripts read that from the run's log.txt and multiply by 4 (tools/python/history_checks.py).
#
#             tip_top: pushed down 1.7 nm; speed 3 m/s at first, then growing as (depth/0.4 nm)^1.25
#             so kinetic energy stays below 2 % of internal energy; x and y held
#          +-----------+
#          |    tip    |   32 nm square column, spherical bottom face tip_surface (R = 27 nm)
#           \_________/
#   +---------------------------+ substrate_top (master surface)
#   |         substrate         |  120 nm wide, 60 nm deep, graded from 0.8 nm at the contact
#   +---------------------------+ substrate_bottom: fixed
#
# What it shows: penalty contact between two deformable bodies (tip_surface -> substrate_top),
# the generated asperity mesh, contact area/radius/force histories and the gap field used to
# measure the contact radius between nodes (compare.py), quasi-static driving (KE << IE is
# checked by compare.py).
begin sierra hertz_coarse_mass_scaled
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0  0.00000
         10.0  0.00375
         20.0  0.01499
         30.0  0.03374
         40.0  0.05999
         50.0  0.08999
         60.0  0.11999
         70.0  0.14999
         80.0  0.17999
         90.0  0.20999
        100.0  0.23999
        110.0  0.26998
        120.0  0.29998
        130.0  0.32998
        140.0  0.35998
        150.0  0.38998
        160.0  0.42062
        170.0  0.45414
        180.0  0.49107
        190.0  0.53183
        200.0  0.57690
        210.0  0.62686
        220.0  0.68233
        230.0  0.74409
        240.0  0.81299
        250.0  0.89005
        260.0  0.97647
        270.0  1.07363
        280.0  1.18318
        290.0  1.30707
        300.0  1.44760
        310.0  1.60754
        315.2  1.70000
        335.2  1.70000
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
      symmetry = quarter
      radius = 27 nm
      tip width = 32 nm
      tip height = 26 nm
      substrate width = 120 nm
      substrate depth = 60 nm
      element size = 0.8 nm
      fine half width = 7.2 nm
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
      termination time = 345 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
      quasi static = on             # run guards: kinetic energy below 5 % of internal energy while loaded
      begin mass scaling
        largest factor = 2                  # target time step = 2 x the unscaled step
        maximum added mass fraction = 0.05  # stop (exit 3) above 5 % added mass
        maximum kinetic energy ratio = 0.1  # stop (exit 3) when KE > 10 % of IE while loaded
      end mass scaling
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = tip_top
        components = x y
      end fixed displacement
      # Symmetry planes of the quarter model. Where they meet the fixed bottom and the tip top (held in x
      # and y) a component is fixed twice, which a fixed displacement allows: on its quarter these are
      # exactly the full model's conditions.
      begin fixed displacement
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
      # A restart file at a stop (CTest verify_hertz_coarse_mass_scaled_restart resumes one).
      begin restart output
        wall time increment = 600 s
      end restart output
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
end sierra hertz_coarse_mass_scaled
