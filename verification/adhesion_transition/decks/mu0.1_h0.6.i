# mu0.1_h0.6.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 0.1, element size 0.6 nm.
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu0.1_h0.6.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu0.1
#
# Paraboloid tip R = 27 nm on a flat, both E = 94.71 GPa, nu = 0.23 (E* = 50 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap - z0 + delta: 40 m/s to delta = -1.565 z0, 4 m/s to 0.935 z0, 8 m/s to 0.401 z0 (P = 2 pi W_c R on the reference) and back to 0.935 z0, 4 m/s to -1.565 z0.
begin sierra mu0.1_h0.6
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
         140.0  5.19957
         145.0  5.37620
         150.0  5.48782
         155.0  5.52762
         160.0  5.53048
         165.0  5.53282
         170.0  5.54165
         175.0  5.55767
         180.0  5.57739
         185.0  5.59739
         190.0  5.61739
         195.0  5.63739
         200.0  5.65739
         205.0  5.67739
         210.0  5.69739
         215.0  5.71739
         220.0  5.73739
         225.0  5.75739
         230.0  5.77739
         235.0  5.79739
         240.0  5.81739
         245.0  5.83739
         250.0  5.85739
         255.0  5.87739
         260.0  5.89739
         265.0  5.91739
         270.0  5.93739
         275.0  5.95739
         280.0  5.97739
         285.0  5.99739
         290.0  6.01739
         295.0  6.03739
         300.0  6.05739
         305.0  6.07739
         310.0  6.09739
         315.0  6.11739
         320.0  6.13739
         325.0  6.15739
         330.0  6.17739
         335.0  6.19739
         340.0  6.21739
         345.0  6.23739
         350.0  6.25678
         355.0  6.27156
         360.0  6.27893
         365.0  6.28043
         370.0  6.27921
         375.0  6.26876
         380.0  6.24350
         385.0  6.20652
         390.0  6.16773
         395.0  6.13814
         400.0  6.12335
         405.0  6.12031
         410.0  6.12152
         415.0  6.13192
         420.0  6.15714
         425.0  6.19410
         430.0  6.23289
         435.0  6.26253
         440.0  6.27737
         445.0  6.28043
         450.0  6.27984
         455.0  6.27466
         460.0  6.26207
         465.0  6.24360
         470.0  6.22361
         475.0  6.20361
         480.0  6.18361
         485.0  6.16361
         490.0  6.14361
         495.0  6.12361
         500.0  6.10361
         505.0  6.08361
         510.0  6.06361
         515.0  6.04361
         520.0  6.02361
         525.0  6.00361
         530.0  5.98361
         535.0  5.96361
         540.0  5.94361
         545.0  5.92361
         550.0  5.90361
         555.0  5.88361
         560.0  5.86361
         565.0  5.84361
         570.0  5.82361
         575.0  5.80361
         580.0  5.78361
         585.0  5.76361
         590.0  5.74361
         595.0  5.72361
         600.0  5.70361
         605.0  5.68361
         610.0  5.66361
         615.0  5.64361
         620.0  5.62361
         625.0  5.60361
         630.0  5.58361
         635.0  5.56365
         640.0  5.54595
         645.0  5.53474
         650.0  5.53073
         653.3  5.53044
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
      element size = 0.6 nm
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
      termination time = 654 ps
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
end sierra mu0.1_h0.6
