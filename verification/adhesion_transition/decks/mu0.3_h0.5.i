# mu0.3_h0.5.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 0.3, element size 0.5 nm.
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu0.3_h0.5.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu0.3
#
# Paraboloid tip R = 27 nm on a flat, both E = 18.227 GPa, nu = 0.23 (E* = 9.6225 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap + delta: 40 m/s to delta = -1.774 z0, 4 m/s to 0.726 z0, 8 m/s to 1.169 z0 (P = 2 pi W_c R on the reference) and back to 0.726 z0, 4 m/s to -1.774 z0.
# Adhesive / element stiffness 16 W h/(E z0^2) = 0.244: time step scale factor 0.9/sqrt(1 + that).
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
         140.0  5.20000
         145.0  5.39996
         150.0  5.58454
         155.0  5.71013
         160.0  5.76173
         165.0  5.76767
         170.0  5.76921
         175.0  5.77665
         180.0  5.79149
         185.0  5.81090
         190.0  5.83090
         195.0  5.85090
         200.0  5.87090
         205.0  5.89090
         210.0  5.91090
         215.0  5.93090
         220.0  5.95090
         225.0  5.97090
         230.0  5.99090
         235.0  6.01090
         240.0  6.03090
         245.0  6.05090
         250.0  6.07090
         255.0  6.09090
         260.0  6.11090
         265.0  6.13090
         270.0  6.15090
         275.0  6.17090
         280.0  6.19090
         285.0  6.21090
         290.0  6.23090
         295.0  6.25090
         300.0  6.27090
         305.0  6.29090
         310.0  6.31090
         315.0  6.33090
         320.0  6.35090
         325.0  6.37090
         330.0  6.39090
         335.0  6.41090
         340.0  6.43090
         345.0  6.45090
         350.0  6.47090
         355.0  6.49060
         360.0  6.50656
         365.0  6.51533
         370.0  6.51762
         375.0  6.51825
         380.0  6.52632
         385.0  6.54879
         390.0  6.58405
         395.0  6.61948
         400.0  6.64198
         405.0  6.65008
         410.0  6.65059
         415.0  6.64603
         420.0  6.62852
         425.0  6.59721
         430.0  6.55927
         435.0  6.53197
         440.0  6.51959
         445.0  6.51766
         450.0  6.51663
         455.0  6.51028
         460.0  6.49647
         465.0  6.47744
         470.0  6.45744
         475.0  6.43744
         480.0  6.41744
         485.0  6.39744
         490.0  6.37744
         495.0  6.35744
         500.0  6.33744
         505.0  6.31744
         510.0  6.29744
         515.0  6.27744
         520.0  6.25744
         525.0  6.23744
         530.0  6.21744
         535.0  6.19744
         540.0  6.17744
         545.0  6.15744
         550.0  6.13744
         555.0  6.11744
         560.0  6.09744
         565.0  6.07744
         570.0  6.05744
         575.0  6.03744
         580.0  6.01744
         585.0  5.99744
         590.0  5.97744
         595.0  5.95744
         600.0  5.93744
         605.0  5.91744
         610.0  5.89744
         615.0  5.87744
         620.0  5.85744
         625.0  5.83744
         630.0  5.81744
         635.0  5.79757
         640.0  5.78074
         645.0  5.77083
         650.0  5.76778
         652.4  5.76766
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
      termination time = 653 ps
      time step scale factor = 0.807
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
end sierra mu0.3_h0.5
