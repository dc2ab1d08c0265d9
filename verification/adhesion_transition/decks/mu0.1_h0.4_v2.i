# mu0.1_h0.4_v2.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 0.1, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu0.1_h0.4_v2.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu0.1
#
# Paraboloid tip R = 27 nm on a flat, both E = 94.71 GPa, nu = 0.23 (E* = 50 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap + delta: 40 m/s to delta = -1.565 z0, 2 m/s to 0.401 z0, 4 m/s to 0.401 z0 (P = 2 pi W_c R on the reference) and back to 0.401 z0, 2 m/s to -1.565 z0.
# Adhesive / element stiffness 16 W h/(E z0^2) = 0.0375: time step scale factor 0.9/sqrt(1 + that).
begin sierra mu0.1_h0.4_v2
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
         170.0  5.83074
         175.0  5.83335
         180.0  5.83967
         185.0  5.84892
         190.0  5.85891
         195.0  5.86891
         200.0  5.87891
         205.0  5.88891
         210.0  5.89891
         215.0  5.90891
         220.0  5.91891
         225.0  5.92891
         230.0  5.93891
         235.0  5.94891
         240.0  5.95891
         245.0  5.96891
         250.0  5.97891
         255.0  5.98891
         260.0  5.99891
         265.0  6.00891
         270.0  6.01891
         275.0  6.02891
         280.0  6.03891
         285.0  6.04891
         290.0  6.05891
         295.0  6.06891
         300.0  6.07891
         305.0  6.08891
         310.0  6.09891
         315.0  6.10891
         320.0  6.11891
         325.0  6.12891
         330.0  6.13891
         335.0  6.14891
         340.0  6.15891
         345.0  6.16891
         350.0  6.17891
         355.0  6.18891
         360.0  6.19891
         365.0  6.20891
         370.0  6.21891
         375.0  6.22891
         380.0  6.23891
         385.0  6.24891
         390.0  6.25891
         395.0  6.26891
         400.0  6.27891
         405.0  6.28891
         410.0  6.29891
         415.0  6.30891
         420.0  6.31891
         425.0  6.32891
         430.0  6.33891
         435.0  6.34891
         440.0  6.35891
         445.0  6.36891
         450.0  6.37891
         455.0  6.38891
         460.0  6.39891
         465.0  6.40859
         470.0  6.41594
         475.0  6.41958
         480.0  6.42031
         485.0  6.41999
         490.0  6.41733
         495.0  6.41097
         500.0  6.40170
         505.0  6.39170
         510.0  6.38170
         515.0  6.37170
         520.0  6.36170
         525.0  6.35170
         530.0  6.34170
         535.0  6.33170
         540.0  6.32170
         545.0  6.31170
         550.0  6.30170
         555.0  6.29170
         560.0  6.28170
         565.0  6.27170
         570.0  6.26170
         575.0  6.25170
         580.0  6.24170
         585.0  6.23170
         590.0  6.22170
         595.0  6.21170
         600.0  6.20170
         605.0  6.19170
         610.0  6.18170
         615.0  6.17170
         620.0  6.16170
         625.0  6.15170
         630.0  6.14170
         635.0  6.13170
         640.0  6.12170
         645.0  6.11170
         650.0  6.10170
         655.0  6.09170
         660.0  6.08170
         665.0  6.07170
         670.0  6.06170
         675.0  6.05170
         680.0  6.04170
         685.0  6.03170
         690.0  6.02170
         695.0  6.01170
         700.0  6.00170
         705.0  5.99170
         710.0  5.98170
         715.0  5.97170
         720.0  5.96170
         725.0  5.95170
         730.0  5.94170
         735.0  5.93170
         740.0  5.92170
         745.0  5.91170
         750.0  5.90170
         755.0  5.89170
         760.0  5.88170
         765.0  5.87170
         770.0  5.86170
         775.0  5.85170
         780.0  5.84204
         785.0  5.83473
         790.0  5.83114
         795.0  5.83044
         795.6  5.83044
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
      termination time = 796 ps
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
end sierra mu0.1_h0.4_v2
