# mu0.1_h0.4.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 0.1, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu0.1_h0.4.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu0.1
#
# Paraboloid tip R = 27 nm on a flat, both E = 94.71 GPa, nu = 0.23 (E* = 50 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap + delta: 40 m/s to delta = -1.565 z0, 4 m/s to 0.401 z0, 8 m/s to 0.401 z0 (P = 2 pi W_c R on the reference) and back to 0.401 z0, 4 m/s to -1.565 z0.
# Adhesive / element stiffness 16 W h/(E z0^2) = 0.0375: time step scale factor 0.9/sqrt(1 + that).
begin sierra mu0.1_h0.4
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.0  0.00000
           5.0  0.00997
          10.0  0.07268
          15.0  0.20997
          20.0  0.40000
          25.0  0.60000
          30.0  0.80000
          35.0  1.00000
          40.0  1.20000
          45.0  1.40000
          50.0  1.60000
          55.0  1.80000
          60.0  2.00000
          65.0  2.20000
          70.0  2.40000
          75.0  2.60000
          80.0  2.80000
          85.0  3.00000
          90.0  3.20000
          95.0  3.40000
         100.0  3.60000
         105.0  3.80000
         110.0  4.00000
         115.0  4.20000
         120.0  4.40000
         125.0  4.60000
         130.0  4.80000
         135.0  5.00000
         140.0  5.20000
         145.0  5.40000
         150.0  5.59387
         155.0  5.74163
         160.0  5.81534
         165.0  5.83040
         170.0  5.83105
         175.0  5.83627
         180.0  5.84890
         185.0  5.86740
         190.0  5.88739
         195.0  5.90739
         200.0  5.92739
         205.0  5.94739
         210.0  5.96739
         215.0  5.98739
         220.0  6.00739
         225.0  6.02739
         230.0  6.04739
         235.0  6.06739
         240.0  6.08739
         245.0  6.10739
         250.0  6.12739
         255.0  6.14739
         260.0  6.16739
         265.0  6.18739
         270.0  6.20739
         275.0  6.22739
         280.0  6.24739
         285.0  6.26739
         290.0  6.28739
         295.0  6.30739
         300.0  6.32739
         305.0  6.34739
         310.0  6.36739
         315.0  6.38735
         320.0  6.40498
         325.0  6.41609
         330.0  6.42003
         335.0  6.42026
         340.0  6.41789
         345.0  6.40901
         350.0  6.39295
         355.0  6.37322
         360.0  6.35322
         365.0  6.33322
         370.0  6.31322
         375.0  6.29322
         380.0  6.27322
         385.0  6.25322
         390.0  6.23322
         395.0  6.21322
         400.0  6.19322
         405.0  6.17322
         410.0  6.15322
         415.0  6.13322
         420.0  6.11322
         425.0  6.09322
         430.0  6.07322
         435.0  6.05322
         440.0  6.03322
         445.0  6.01322
         450.0  5.99322
         455.0  5.97322
         460.0  5.95322
         465.0  5.93322
         470.0  5.91322
         475.0  5.89322
         480.0  5.87322
         485.0  5.85386
         490.0  5.83917
         495.0  5.83190
         500.0  5.83044
         500.7  5.83044
    end values
  end function push
  begin property specification for material soft
    density = 1370.65 kg/m^3
    begin parameters for model elastic
      youngs modulus = 94.71 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material soft
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8
  begin finite element model asperity
    begin generated asperity
      symmetry = quarter
      tip profile = paraboloid
      radius = 27 nm
      gap = 6.3 nm
      tip width = 24 nm
      tip height = 12 nm
      substrate width = 80 nm
      substrate depth = 40 nm
      element size = 0.4 nm
      fine half width = 5 nm
      fine depth = 2 nm
      grading ratio = 1.35
    end generated asperity
    begin parameters for block tip
      material = soft
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = soft
      section = hex8
    end parameters for block substrate
  end finite element model asperity
  begin presto procedure indent
    begin time control
      termination time = 501 ps
      time step scale factor = 0.884
      viscous dissipation = exact
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 1e+11 1/s
      quasi static = on
      begin fixed displacement
        node set = symmetry_x
        components = x
      end fixed displacement
      begin fixed displacement
        node set = symmetry_y
        components = y
      end fixed displacement
      begin fixed displacement
        node set = substrate_bottom
        components = z
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
          adhesion cutoff = 6 nm
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 2 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
    end presto region main
  end presto procedure indent
end sierra mu0.1_h0.4
