# mu1_h0.3.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 1, element size 0.3 nm.
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu1_h0.3.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu1
#
# Paraboloid tip R = 27 nm on a flat, both E = 2.995 GPa, nu = 0.23 (E* = 1.5811 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap - z0 + delta: 40 m/s to delta = -3.124 z0, 4 m/s to 0.118 z0, 8 m/s to 3.805 z0 (P = 2 pi W_c R on the reference) and back to 0.118 z0, 4 m/s to -3.238 z0.
begin sierra mu1_h0.3
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
         130.0  4.79673
         135.0  4.95490
         140.0  5.04074
         145.0  5.06256
         150.0  5.06320
         155.0  5.06738
         160.0  5.07880
         165.0  5.09662
         170.0  5.11659
         175.0  5.13659
         180.0  5.15659
         185.0  5.17659
         190.0  5.19659
         195.0  5.21659
         200.0  5.23659
         205.0  5.25659
         210.0  5.27659
         215.0  5.29659
         220.0  5.31659
         225.0  5.33659
         230.0  5.35659
         235.0  5.37659
         240.0  5.39659
         245.0  5.41659
         250.0  5.43659
         255.0  5.45659
         260.0  5.47659
         265.0  5.49659
         270.0  5.51659
         275.0  5.53659
         280.0  5.55659
         285.0  5.57659
         290.0  5.59659
         295.0  5.61659
         300.0  5.63659
         305.0  5.65659
         310.0  5.67659
         315.0  5.69659
         320.0  5.71659
         325.0  5.73659
         330.0  5.75659
         335.0  5.77659
         340.0  5.79659
         345.0  5.81659
         350.0  5.83659
         355.0  5.85659
         360.0  5.87659
         365.0  5.89659
         370.0  5.91659
         375.0  5.93659
         380.0  5.95659
         385.0  5.97659
         390.0  5.99659
         395.0  6.01542
         400.0  6.02874
         405.0  6.03461
         410.0  6.03545
         415.0  6.03780
         420.0  6.05115
         425.0  6.07940
         430.0  6.11772
         435.0  6.15772
         440.0  6.19772
         445.0  6.23772
         450.0  6.27772
         455.0  6.31772
         460.0  6.35772
         465.0  6.39772
         470.0  6.43772
         475.0  6.47772
         480.0  6.51772
         485.0  6.55772
         490.0  6.59772
         495.0  6.63772
         500.0  6.67772
         505.0  6.71772
         510.0  6.75772
         515.0  6.79772
         520.0  6.83772
         525.0  6.87772
         530.0  6.91772
         535.0  6.95772
         540.0  6.99772
         545.0  7.03772
         550.0  7.07758
         555.0  7.11233
         560.0  7.13375
         565.0  7.14101
         570.0  7.14129
         575.0  7.13604
         580.0  7.11746
         585.0  7.08472
         590.0  7.04514
         595.0  7.00514
         600.0  6.96514
         605.0  6.92514
         610.0  6.88514
         615.0  6.84514
         620.0  6.80514
         625.0  6.76514
         630.0  6.72514
         635.0  6.68514
         640.0  6.64514
         645.0  6.60514
         650.0  6.56514
         655.0  6.52514
         660.0  6.48514
         665.0  6.44514
         670.0  6.40514
         675.0  6.36514
         680.0  6.32514
         685.0  6.28514
         690.0  6.24514
         695.0  6.20514
         700.0  6.16514
         705.0  6.12514
         710.0  6.08602
         715.0  6.05529
         720.0  6.03921
         725.0  6.03548
         730.0  6.03501
         735.0  6.03038
         740.0  6.01842
         745.0  6.00028
         750.0  5.98030
         755.0  5.96030
         760.0  5.94030
         765.0  5.92030
         770.0  5.90030
         775.0  5.88030
         780.0  5.86030
         785.0  5.84030
         790.0  5.82030
         795.0  5.80030
         800.0  5.78030
         805.0  5.76030
         810.0  5.74030
         815.0  5.72030
         820.0  5.70030
         825.0  5.68030
         830.0  5.66030
         835.0  5.64030
         840.0  5.62030
         845.0  5.60030
         850.0  5.58030
         855.0  5.56030
         860.0  5.54030
         865.0  5.52030
         870.0  5.50030
         875.0  5.48030
         880.0  5.46030
         885.0  5.44030
         890.0  5.42030
         895.0  5.40030
         900.0  5.38030
         905.0  5.36030
         910.0  5.34030
         915.0  5.32030
         920.0  5.30030
         925.0  5.28030
         930.0  5.26030
         935.0  5.24030
         940.0  5.22030
         945.0  5.20030
         950.0  5.18030
         955.0  5.16030
         960.0  5.14030
         965.0  5.12030
         970.0  5.10030
         975.0  5.08030
         980.0  5.06037
         985.0  5.04306
         990.0  5.03245
         995.0  5.02890
         997.9  5.02870
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
      element size = 0.3 nm
      fine half width = 8.5 nm
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
      termination time = 998 ps
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
end sierra mu1_h0.3
