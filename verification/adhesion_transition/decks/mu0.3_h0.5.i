# mu0.3_h0.5.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 0.3, element size 0.5 nm.
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu0.3_h0.5.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu0.3
#
# Paraboloid tip R = 27 nm on a flat, both E = 18.227 GPa, nu = 0.23 (E* = 9.6225 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap - z0 + delta: 40 m/s to delta = -1.774 z0, 4 m/s to 0.726 z0, 8 m/s to 1.169 z0 (P = 2 pi W_c R on the reference) and back to 0.726 z0, 4 m/s to -1.774 z0.
begin sierra mu0.3_h0.5
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
         140.0  5.19706
         145.0  5.35669
         150.0  5.44434
         155.0  5.46727
         160.0  5.46796
         165.0  5.47199
         170.0  5.48323
         175.0  5.50094
         180.0  5.52090
         185.0  5.54090
         190.0  5.56090
         195.0  5.58090
         200.0  5.60090
         205.0  5.62090
         210.0  5.64090
         215.0  5.66090
         220.0  5.68090
         225.0  5.70090
         230.0  5.72090
         235.0  5.74090
         240.0  5.76090
         245.0  5.78090
         250.0  5.80090
         255.0  5.82090
         260.0  5.84090
         265.0  5.86090
         270.0  5.88090
         275.0  5.90090
         280.0  5.92090
         285.0  5.94090
         290.0  5.96090
         295.0  5.98090
         300.0  6.00090
         305.0  6.02090
         310.0  6.04090
         315.0  6.06090
         320.0  6.08090
         325.0  6.10090
         330.0  6.12090
         335.0  6.14090
         340.0  6.16090
         345.0  6.18089
         350.0  6.19935
         355.0  6.21191
         360.0  6.21707
         365.0  6.21767
         370.0  6.22075
         375.0  6.23564
         380.0  6.26531
         385.0  6.30295
         390.0  6.33266
         395.0  6.34757
         400.0  6.35066
         405.0  6.34949
         410.0  6.33920
         415.0  6.31411
         420.0  6.27749
         425.0  6.24383
         430.0  6.22400
         435.0  6.21790
         440.0  6.21753
         445.0  6.21436
         450.0  6.20427
         455.0  6.18732
         460.0  6.16744
         465.0  6.14744
         470.0  6.12744
         475.0  6.10744
         480.0  6.08744
         485.0  6.06744
         490.0  6.04744
         495.0  6.02744
         500.0  6.00744
         505.0  5.98744
         510.0  5.96744
         515.0  5.94744
         520.0  5.92744
         525.0  5.90744
         530.0  5.88744
         535.0  5.86744
         540.0  5.84744
         545.0  5.82744
         550.0  5.80744
         555.0  5.78744
         560.0  5.76744
         565.0  5.74744
         570.0  5.72744
         575.0  5.70744
         580.0  5.68744
         585.0  5.66744
         590.0  5.64744
         595.0  5.62744
         600.0  5.60744
         605.0  5.58744
         610.0  5.56744
         615.0  5.54744
         620.0  5.52744
         625.0  5.50744
         630.0  5.48847
         635.0  5.47482
         640.0  5.46863
         644.9  5.46766
    end values
  end function push
  begin property specification for material soft
    density = 263.781 kg/m^3
    begin parameters for model elastic
      youngs modulus = 18.2269 GPa
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
      fine half width = 6 nm
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
      termination time = 645 ps
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
end sierra mu0.3_h0.5
