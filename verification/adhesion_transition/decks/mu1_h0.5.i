# mu1_h0.5.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 1, element size 0.5 nm.
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu1_h0.5.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu1
#
# Paraboloid tip R = 27 nm on a flat, both E = 2.995 GPa, nu = 0.23 (E* = 1.5811 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap + delta: 80 m/s to delta = -3.124 z0, 8 m/s to -0.382 z0, 24 m/s to 2.977 z0 (P = 1 pi W_c R on the reference) and back to -0.382 z0, 8 m/s to -3.238 z0.
# Adhesive / element stiffness 16 W h/(E z0^2) = 1.48: time step scale factor 0.9/sqrt(1 + that).
begin sierra mu1_h0.5
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.0  0.00000
           5.0  0.01994
          10.0  0.14535
          15.0  0.41994
          20.0  0.80000
          25.0  1.20000
          30.0  1.60000
          35.0  2.00000
          40.0  2.40000
          45.0  2.80000
          50.0  3.20000
          55.0  3.60000
          60.0  4.00000
          65.0  4.40000
          70.0  4.79576
          75.0  5.12317
          80.0  5.30898
          85.0  5.36149
          90.0  5.36330
          95.0  5.37056
         100.0  5.39198
         105.0  5.42673
         110.0  5.46659
         115.0  5.50659
         120.0  5.54659
         125.0  5.58659
         130.0  5.62659
         135.0  5.66659
         140.0  5.70659
         145.0  5.74659
         150.0  5.78659
         155.0  5.82659
         160.0  5.86659
         165.0  5.90659
         170.0  5.94659
         175.0  5.98659
         180.0  6.02659
         185.0  6.06659
         190.0  6.10659
         195.0  6.14442
         200.0  6.17148
         205.0  6.18362
         210.0  6.18545
         215.0  6.19195
         220.0  6.23078
         225.0  6.31435
         230.0  6.42885
         235.0  6.54885
         240.0  6.66885
         245.0  6.78885
         250.0  6.90885
         255.0  7.02732
         260.0  7.12422
         265.0  7.17823
         270.0  7.19287
         275.0  7.19165
         280.0  7.16854
         285.0  7.10255
         290.0  6.99719
         295.0  6.87750
         300.0  6.75750
         305.0  6.63750
         310.0  6.51750
         315.0  6.39758
         320.0  6.28853
         325.0  6.21636
         330.0  6.18819
         335.0  6.18543
         340.0  6.18178
         345.0  6.16584
         350.0  6.13523
         355.0  6.09614
         360.0  6.05614
         365.0  6.01614
         370.0  5.97614
         375.0  5.93614
         380.0  5.89614
         385.0  5.85614
         390.0  5.81614
         395.0  5.77614
         400.0  5.73614
         405.0  5.69614
         410.0  5.65614
         415.0  5.61614
         420.0  5.57614
         425.0  5.53614
         430.0  5.49614
         435.0  5.45614
         440.0  5.41614
         445.0  5.37722
         450.0  5.34722
         455.0  5.33198
         460.0  5.32871
         460.9  5.32870
    end values
  end function push
  begin property specification for material soft
    density = 43.3437 kg/m^3
    begin parameters for model elastic
      youngs modulus = 2.99499 GPa
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
      element size = 0.5 nm
      fine half width = 7.5 nm
      fine depth = 2 nm
      grading ratio = 1.6
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
      termination time = 461 ps
      time step scale factor = 0.571
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
end sierra mu1_h0.5
