# hertz_fine_mixed.i -- mixed blocks (issue 24): hertz_fine.i with the tip and substrate in one-point
# (mean-quadrature) elements except a fully integrated skin of 1 element layer(s) under the
# contact surfaces (tip_surface, substrate_top; `begin surface layer block`). Same mesh, loading
# and check (same tolerance) as hertz_fine.i; figures in README.md.
#
# hertz_fine.i: Hertz contact of a silicon asperity (R = 27 nm) on a silicon flat, frictionless,
# no adhesion: the fine variant (label slow) (verification/hertz/README.md). Its tip is Hertz's
# paraboloid z = r^2/(2R), the profile for which a^3 = 3PR/(4E*) is exact (the coarse variant's
# sphere differs from it by 0.85 % in a at a/R = 0.25), so the 1.5 % check measures the solver.
#
# Run:    build/bin/tribex run verification/hertz/hertz_fine_mixed.i -o hertz_fine_mixed_output
# Check:  /usr/bin/python3 verification/hertz/compare.py hertz_fine_mixed_output --element-size 0.5 --tolerance 0.015 --min-radius 4.0
#         (the loads the coarse variant compares, a_H >= 4.0 nm: the refinement study; README.md)
#
#             tip_top: pushed down 1.7 nm; speed 2 m/s at first, then growing as (depth/0.3 nm)^1.25
#             so kinetic energy stays below 2 % of internal energy; x and y held
#          +-----------+
#          |    tip    |   32 nm square column, paraboloidal bottom face tip_surface (R = 27 nm)
#           \_________/
#   +---------------------------+ substrate_top (master surface)
#   |         substrate         |  200 nm wide, 120 nm deep, graded from 0.5 nm at the contact
#   +---------------------------+ substrate_bottom: fixed
#
# What it shows: penalty contact between two deformable bodies (tip_surface -> substrate_top),
# the generated asperity mesh, contact area/radius/force histories and the gap field used to
# measure the contact radius between nodes (compare.py), quasi-static driving (KE << IE is
# checked by compare.py).
begin sierra hertz_fine_mixed
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0  0.00000
          6.0  0.00090
         12.0  0.00360
         18.0  0.00810
         24.0  0.01439
         30.0  0.02249
         36.0  0.03239
         42.0  0.04399
         48.0  0.05599
         54.0  0.06799
         60.0  0.07999
         66.0  0.09199
         72.0  0.10399
         78.0  0.11599
         84.0  0.12799
         90.0  0.13999
         96.0  0.15199
        102.0  0.16399
        108.0  0.17599
        114.0  0.18799
        120.0  0.19999
        126.0  0.21199
        132.0  0.22399
        138.0  0.23599
        144.0  0.24799
        150.0  0.25999
        156.0  0.27199
        162.0  0.28399
        168.0  0.29599
        174.0  0.30812
        180.0  0.32085
        186.0  0.33424
        192.0  0.34833
        198.0  0.36318
        204.0  0.37883
        210.0  0.39532
        216.0  0.41273
        222.0  0.43110
        228.0  0.45051
        234.0  0.47102
        240.0  0.49272
        246.0  0.51567
        252.0  0.53998
        258.0  0.56574
        264.0  0.59305
        270.0  0.62203
        276.0  0.65281
        282.0  0.68551
        288.0  0.72028
        294.0  0.75728
        300.0  0.79670
        306.0  0.83871
        312.0  0.88353
        318.0  0.93138
        324.0  0.98251
        330.0  1.03721
        336.0  1.09576
        342.0  1.15850
        348.0  1.22580
        354.0  1.29806
        360.0  1.37572
        366.0  1.45927
        372.0  1.54927
        378.0  1.64631
        381.1  1.70013
        401.1  1.70000
    end values
  end function push

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon

  # The concentrated penalty forces of node-to-face contact excite the hourglass modes of one-point
  # elements at the surface (README.md):
  # mixed blocks, hex8 (fully integrated) for the skins tip_skin and substrate_skin, where the
  # penalty point forces act; hex8_mq (one point) for the rest of tip and substrate.
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8
  begin solid section hex8_mq
    formulation = mean_quadrature
  end solid section hex8_mq

  begin finite element model asperity
    begin generated asperity
      radius = 27 nm
      tip profile = paraboloid
      tip width = 32 nm
      tip height = 26 nm
      substrate width = 200 nm
      substrate depth = 120 nm
      element size = 0.5 nm
      fine half width = 7.2 nm
      fine depth = 2.5 nm
      grading ratio = 1.35
    end generated asperity
    begin surface layer block tip_skin
      from block = tip
      surface = tip_surface
      layers = 1
    end surface layer block tip_skin
    begin surface layer block substrate_skin
      from block = substrate
      surface = substrate_top
      layers = 1
    end surface layer block substrate_skin
    begin parameters for block tip
      material = silicon
      section = hex8_mq
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8_mq
    end parameters for block substrate
    begin parameters for block tip_skin
      material = silicon
      section = hex8
    end parameters for block tip_skin
    begin parameters for block substrate_skin
      material = silicon
      section = hex8
    end parameters for block substrate_skin
  end finite element model asperity

  begin presto procedure indent
    begin time control
      termination time = 411 ps
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
end sierra hertz_fine_mixed
