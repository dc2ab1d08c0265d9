# mu1_h0.4.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 1, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu1_h0.4.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu1
#
# Paraboloid tip R = 27 nm on a flat, both E = 2.995 GPa, nu = 0.23 (E* = 1.5811 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap + delta: 40 m/s to delta = -3.124 z0, 4 m/s to 0.118 z0, 8 m/s to 3.805 z0 (P = 2 pi W_c R on the reference) and back to 0.118 z0, 4 m/s to -3.238 z0.
# Adhesive / element stiffness 16 W h/(E z0^2) = 1.19: time step scale factor 0.3 (0.9/sqrt(1 + that) = 0.609 reported an energy error that was the ledger's, README.md "Time step").
begin sierra mu1_h0.4
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
         135.0  4.99993
         140.0  5.18359
         145.0  5.30741
         150.0  5.35743
         155.0  5.36288
         160.0  5.36452
         165.0  5.37213
         170.0  5.38713
         175.0  5.40659
         180.0  5.42659
         185.0  5.44659
         190.0  5.46659
         195.0  5.48659
         200.0  5.50659
         205.0  5.52659
         210.0  5.54659
         215.0  5.56659
         220.0  5.58659
         225.0  5.60659
         230.0  5.62659
         235.0  5.64659
         240.0  5.66659
         245.0  5.68659
         250.0  5.70659
         255.0  5.72659
         260.0  5.74659
         265.0  5.76659
         270.0  5.78659
         275.0  5.80659
         280.0  5.82659
         285.0  5.84659
         290.0  5.86659
         295.0  5.88659
         300.0  5.90659
         305.0  5.92659
         310.0  5.94659
         315.0  5.96659
         320.0  5.98659
         325.0  6.00659
         330.0  6.02659
         335.0  6.04659
         340.0  6.06659
         345.0  6.08659
         350.0  6.10659
         355.0  6.12659
         360.0  6.14659
         365.0  6.16659
         370.0  6.18659
         375.0  6.20659
         380.0  6.22659
         385.0  6.24659
         390.0  6.26659
         395.0  6.28659
         400.0  6.30641
         405.0  6.32299
         410.0  6.33256
         415.0  6.33537
         420.0  6.33581
         425.0  6.34265
         430.0  6.36352
         435.0  6.39790
         440.0  6.43772
         445.0  6.47772
         450.0  6.51772
         455.0  6.55772
         460.0  6.59772
         465.0  6.63772
         470.0  6.67772
         475.0  6.71772
         480.0  6.75772
         485.0  6.79772
         490.0  6.83772
         495.0  6.87772
         500.0  6.91772
         505.0  6.95772
         510.0  6.99772
         515.0  7.03772
         520.0  7.07772
         525.0  7.11772
         530.0  7.15772
         535.0  7.19772
         540.0  7.23772
         545.0  7.27772
         550.0  7.31772
         555.0  7.35772
         560.0  7.39622
         565.0  7.42497
         570.0  7.43884
         575.0  7.44143
         580.0  7.43993
         585.0  7.42868
         590.0  7.40255
         595.0  7.36514
         600.0  7.32514
         605.0  7.28514
         610.0  7.24514
         615.0  7.20514
         620.0  7.16514
         625.0  7.12514
         630.0  7.08514
         635.0  7.04514
         640.0  7.00514
         645.0  6.96514
         650.0  6.92514
         655.0  6.88514
         660.0  6.84514
         665.0  6.80514
         670.0  6.76514
         675.0  6.72514
         680.0  6.68514
         685.0  6.64514
         690.0  6.60514
         695.0  6.56514
         700.0  6.52514
         705.0  6.48514
         710.0  6.44514
         715.0  6.40517
         720.0  6.36904
         725.0  6.34535
         730.0  6.33628
         735.0  6.33544
         740.0  6.33351
         745.0  6.32535
         750.0  6.30988
         755.0  6.29030
         760.0  6.27030
         765.0  6.25030
         770.0  6.23030
         775.0  6.21030
         780.0  6.19030
         785.0  6.17030
         790.0  6.15030
         795.0  6.13030
         800.0  6.11030
         805.0  6.09030
         810.0  6.07030
         815.0  6.05030
         820.0  6.03030
         825.0  6.01030
         830.0  5.99030
         835.0  5.97030
         840.0  5.95030
         845.0  5.93030
         850.0  5.91030
         855.0  5.89030
         860.0  5.87030
         865.0  5.85030
         870.0  5.83030
         875.0  5.81030
         880.0  5.79030
         885.0  5.77030
         890.0  5.75030
         895.0  5.73030
         900.0  5.71030
         905.0  5.69030
         910.0  5.67030
         915.0  5.65030
         920.0  5.63030
         925.0  5.61030
         930.0  5.59030
         935.0  5.57030
         940.0  5.55030
         945.0  5.53030
         950.0  5.51030
         955.0  5.49030
         960.0  5.47030
         965.0  5.45030
         970.0  5.43030
         975.0  5.41030
         980.0  5.39030
         985.0  5.37030
         990.0  5.35108
         995.0  5.33679
        1000.0  5.32995
        1005.0  5.32870
        1005.4  5.32870
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
      element size = 0.4 nm
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
      termination time = 1006 ps
      time step scale factor = 0.3
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
end sierra mu1_h0.4
