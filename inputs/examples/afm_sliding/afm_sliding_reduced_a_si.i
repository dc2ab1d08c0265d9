# afm_sliding_reduced_a_si.i -- written by make_decks.py (edit that, not this file).
# AFM sliding example (a) silicon on silicon, reduced variant (the report's Section 3.5, Fig. 3.9): a silicon sphere
# (R = 50 nm, a 26 nm wide die) pressed with 500 nN into the di-3 AFM surface (10 um polysilicon
# scan, levelled, bicubic spline) and slid 3 nm along the track (+y) at 7.5 m/s.
# Junction model: W = 0.05 J/m^2, z0 = 0.3 nm, cutoff 6 nm, tau* = 195 MPa (Si on Si, as verification/sphere_sliding).
#
# Run:    build/bin/tribex run inputs/examples/afm_sliding/afm_sliding_reduced_a_si.i -o afm_sliding_reduced_a_si_output
# Plot:   /usr/bin/python3 inputs/examples/afm_sliding/afm_sliding.py afm_sliding_reduced_a_si_output ...  (see README.md)
#
# Time line: 0 - 80 ps load ramp to 500 nN (load control on tip_top z: a total force shared by
# its nodes; the tip starts 0.3 nm above first touch), 80 - 140 ps hold, then tip_top
# moves in +y at 7.5 m/s (cycloidal 40 ps ramp) to 560 ps; tip_top x is fixed.
# Substrate: bottom fixed (it carries the 500 nN; a dashpot alone cannot hold a static load), silent
# boundaries on the four sides (absorb the waves of the load and the sliding).
# Quasi-static: mass damping 5e11 1/s (about half critical for the tip bouncing on the contact
# stiffness); the check is kinetic / internal energy at the end of the hold (afm_sliding.py).
begin sierra afm_sliding_reduced_a_si
  begin function load
    type = piecewise linear
    abscissa unit = ps
    begin values
           0.0  0.00000
           5.0  0.00961
          10.0  0.03806
          15.0  0.08427
          20.0  0.14645
          25.0  0.22221
          30.0  0.30866
          35.0  0.40245
          40.0  0.50000
          45.0  0.59755
          50.0  0.69134
          55.0  0.77779
          60.0  0.85355
          65.0  0.91573
          70.0  0.96194
          75.0  0.99039
          80.0  1.00000
          85.0  1.00000
          90.0  1.00000
          95.0  1.00000
         100.0  1.00000
         105.0  1.00000
         110.0  1.00000
         115.0  1.00000
         120.0  1.00000
         125.0  1.00000
         130.0  1.00000
         135.0  1.00000
         140.0  1.00000
         145.0  1.00000
         150.0  1.00000
         155.0  1.00000
         160.0  1.00000
         165.0  1.00000
         170.0  1.00000
         175.0  1.00000
         180.0  1.00000
         185.0  1.00000
         190.0  1.00000
         195.0  1.00000
         200.0  1.00000
         205.0  1.00000
         210.0  1.00000
         215.0  1.00000
         220.0  1.00000
         225.0  1.00000
         230.0  1.00000
         235.0  1.00000
         240.0  1.00000
         245.0  1.00000
         250.0  1.00000
         255.0  1.00000
         260.0  1.00000
         265.0  1.00000
         270.0  1.00000
         275.0  1.00000
         280.0  1.00000
         285.0  1.00000
         290.0  1.00000
         295.0  1.00000
         300.0  1.00000
         305.0  1.00000
         310.0  1.00000
         315.0  1.00000
         320.0  1.00000
         325.0  1.00000
         330.0  1.00000
         335.0  1.00000
         340.0  1.00000
         345.0  1.00000
         350.0  1.00000
         355.0  1.00000
         360.0  1.00000
         365.0  1.00000
         370.0  1.00000
         375.0  1.00000
         380.0  1.00000
         385.0  1.00000
         390.0  1.00000
         395.0  1.00000
         400.0  1.00000
         405.0  1.00000
         410.0  1.00000
         415.0  1.00000
         420.0  1.00000
         425.0  1.00000
         430.0  1.00000
         435.0  1.00000
         440.0  1.00000
         445.0  1.00000
         450.0  1.00000
         455.0  1.00000
         460.0  1.00000
         465.0  1.00000
         470.0  1.00000
         475.0  1.00000
         480.0  1.00000
         485.0  1.00000
         490.0  1.00000
         495.0  1.00000
         500.0  1.00000
         505.0  1.00000
         510.0  1.00000
         515.0  1.00000
         520.0  1.00000
         525.0  1.00000
         530.0  1.00000
         535.0  1.00000
         540.0  1.00000
         545.0  1.00000
         550.0  1.00000
         555.0  1.00000
         560.0  1.00000
    end values
  end function load
  begin function slide
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.0  0.00000
           5.0  0.00000
          10.0  0.00000
          15.0  0.00000
          20.0  0.00000
          25.0  0.00000
          30.0  0.00000
          35.0  0.00000
          40.0  0.00000
          45.0  0.00000
          50.0  0.00000
          55.0  0.00000
          60.0  0.00000
          65.0  0.00000
          70.0  0.00000
          75.0  0.00000
          80.0  0.00000
          85.0  0.00000
          90.0  0.00000
          95.0  0.00000
         100.0  0.00000
         105.0  0.00000
         110.0  0.00000
         115.0  0.00000
         120.0  0.00000
         125.0  0.00000
         130.0  0.00000
         135.0  0.00000
         140.0  0.00000
         145.0  0.00048
         150.0  0.00374
         155.0  0.01214
         160.0  0.02725
         165.0  0.04964
         170.0  0.07874
         175.0  0.11298
         180.0  0.15000
         185.0  0.18750
         190.0  0.22500
         195.0  0.26250
         200.0  0.30000
         205.0  0.33750
         210.0  0.37500
         215.0  0.41250
         220.0  0.45000
         225.0  0.48750
         230.0  0.52500
         235.0  0.56250
         240.0  0.60000
         245.0  0.63750
         250.0  0.67500
         255.0  0.71250
         260.0  0.75000
         265.0  0.78750
         270.0  0.82500
         275.0  0.86250
         280.0  0.90000
         285.0  0.93750
         290.0  0.97500
         295.0  1.01250
         300.0  1.05000
         305.0  1.08750
         310.0  1.12500
         315.0  1.16250
         320.0  1.20000
         325.0  1.23750
         330.0  1.27500
         335.0  1.31250
         340.0  1.35000
         345.0  1.38750
         350.0  1.42500
         355.0  1.46250
         360.0  1.50000
         365.0  1.53750
         370.0  1.57500
         375.0  1.61250
         380.0  1.65000
         385.0  1.68750
         390.0  1.72500
         395.0  1.76250
         400.0  1.80000
         405.0  1.83750
         410.0  1.87500
         415.0  1.91250
         420.0  1.95000
         425.0  1.98750
         430.0  2.02500
         435.0  2.06250
         440.0  2.10000
         445.0  2.13750
         450.0  2.17500
         455.0  2.21250
         460.0  2.25000
         465.0  2.28750
         470.0  2.32500
         475.0  2.36250
         480.0  2.40000
         485.0  2.43750
         490.0  2.47500
         495.0  2.51250
         500.0  2.55000
         505.0  2.58750
         510.0  2.62500
         515.0  2.66250
         520.0  2.70000
         525.0  2.73750
         530.0  2.77500
         535.0  2.81250
         540.0  2.85000
         545.0  2.88750
         550.0  2.92500
         555.0  2.96250
         560.0  3.00000
    end values
  end function slide

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon

  # Fully integrated at GPa contact pressures (verification/hertz/README.md).
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8

  begin finite element model afm_track
    begin afm surface
      file = ../../../../shared/data/afm/di-3.di
      channel = 0
      window = 102 153 40 36 nm
      track = 106 156 28 30 nm
      element size = 1.0 nm
      depth = 15 nm
      grading ratio = 1.3
    end afm surface
    begin generated asperity
      substrate = none
      radius = 50 nm
      tip width = 26 nm
      tip height = 8 nm
      element size = 1.0 nm
      fine half width = 11 nm
      fine depth = 2 nm
      grading ratio = 1.3
      apex position = 120 170 37.9126 nm
    end generated asperity
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
  end finite element model afm_track

  begin presto procedure press_and_slide
    begin time control
      termination time = 560.0 ps
    end time control
    begin presto region main
      use finite element model afm_track
      mass damping coefficient = 5e11 1/s
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin silent boundary
        side set = substrate_sides
      end silent boundary
      begin fixed displacement
        node set = tip_top
        components = x
      end fixed displacement
      begin prescribed force
        node set = tip_top
        component = z
        function = load
        scale factor = -500 nN
      end prescribed force
      begin prescribed displacement
        node set = tip_top
        component = y
        function = slide
      end prescribed displacement
      begin contact definition tip_on_track
        contact surface tip contains tip_surface
        contact surface track contains substrate_top
        contact axis = 120 170 0 0 0 1 nm
        begin interaction junction
          surfaces = tip track
          model = junction
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm
          junction strength = 195 MPa
          junction reference speed = 0.1 m/s   # backward Euler: tanh(V/v_ref) = 1 in sliding
          junction gap tolerance = 0 nm
        end interaction junction
      end contact definition tip_on_track
      begin history output hist
        time increment = 2 ps
        reaction force = substrate_bottom
        mean displacement = tip_top tip_apex
      end history output hist
      begin results output fields
        time increment = 100 ps
        nodal variables = displacement contact_traction contact_status
      end results output fields
    end presto region main
  end presto procedure press_and_slide
end sierra afm_sliding_reduced_a_si
