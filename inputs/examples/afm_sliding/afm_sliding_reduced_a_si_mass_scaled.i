# afm_sliding_reduced_a_si_mass_scaled.i -- written by make_decks.py (edit that, not this file).
# AFM sliding example (a) silicon on silicon, reduced variant (the report's Section 3.5, Fig. 3.9): a silicon sphere
# (R = 50 nm, a 26 nm wide die) pressed with 500 nN into the di-3 AFM surface (10 um polysilicon
# scan, levelled, bicubic spline) and slid 3 nm along the track (+y) at 7.5 m/s.
# Junction model: W = 0.05 J/m^2, z0 = 0.3 nm, cutoff 6 nm, tau* = 195 MPa (Si on Si, as verification/sphere_sliding).
#
# Run:    build/bin/tribex run inputs/examples/afm_sliding/afm_sliding_reduced_a_si_mass_scaled.i -o afm_sliding_reduced_a_si_mass_scaled_output
# Plot:   /usr/bin/python3 inputs/examples/afm_sliding/afm_sliding.py afm_sliding_reduced_a_si_mass_scaled_output ...  (see README.md)
#
# Time line: 0 - 80 ps load ramp to 500 nN (load control on z of tip_body, the tip top as a rigid
# body; the tip starts 0.3 nm above first touch), 80 - 980 ps hold, then tip_body
# moves in +y at 7.5 m/s (cycloidal 40 ps ramp) to 1400 ps; its x is fixed.
# Substrate: bottom fixed (it carries the 500 nN; a dashpot alone cannot hold a static load), silent
# boundaries on the four sides (absorb the waves of the load and the sliding).
# Quasi-static: mass damping 5e11 1/s (about half critical for the tip bouncing on the contact
# stiffness); the check is kinetic / internal energy at the end of the hold (afm_sliding.py).
# END: the termination time; CI stops the reduced decks at 1.5 nm of sliding (afm_sliding.py --set, README.md).
{END = 1400.0 ps}
begin sierra afm_sliding_reduced_a_si_mass_scaled
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
        1400.0  1.00000
    end values
  end function load
  begin function slide
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.0  0.00000
         980.0  0.00000
         985.0  0.00048
         990.0  0.00374
         995.0  0.01214
        1000.0  0.02725
        1005.0  0.04964
        1010.0  0.07874
        1015.0  0.11298
        1020.0  0.15000
        1400.0  3.00000
    end values
  end function slide

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon

  # Fully integrated at GPa contact pressures (verification/hertz/README.md): the skin blocks under
  # the contact surfaces (tip_skin, and substrate_skin or coating_skin); mean quadrature elsewhere.
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8
  begin solid section hex8_mq
    formulation = mean_quadrature
  end solid section hex8_mq

  begin finite element model afm_track
    begin afm surface
      file = ../../data/afm/di-3.di
      channel = 0
      window = 102 153 40 36 nm
      small window = interpolate   # di-3 has 39 nm pixels: the window is the spline between them
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
    begin surface layer block tip_skin
      from block = tip
      surface = tip_surface
      layers = 2
    end surface layer block tip_skin
    begin surface layer block substrate_skin
      from block = substrate
      surface = substrate_top
      layers = 2
    end surface layer block substrate_skin
    begin parameters for block tip
      material = silicon
      section = hex8_mq
    end parameters for block tip
    begin parameters for block tip_skin
      material = silicon
      section = hex8
    end parameters for block tip_skin
    begin parameters for block substrate
      material = silicon
      section = hex8_mq
    end parameters for block substrate
    begin parameters for block substrate_skin
      material = silicon
      section = hex8
    end parameters for block substrate_skin
  end finite element model afm_track

  begin presto procedure press_and_slide
    begin time control
      termination time = {END}
    end time control
    begin presto region main
      use finite element model afm_track
      mass damping coefficient = 5e11 1/s
      begin mass scaling
        largest factor = 8                  # target time step = 8 x the unscaled step
        maximum added mass fraction = 35
      end mass scaling
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin silent boundary
        side set = substrate_sides
      end silent boundary
      begin rigid body tip_body
        node set = tip_top
      end rigid body tip_body
      begin fixed displacement
        node set = tip_body
        components = x
      end fixed displacement
      begin prescribed force
        rigid body = tip_body
        component = z
        function = load
        scale factor = -500 nN
      end prescribed force
      begin prescribed displacement
        rigid body = tip_body
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
end sierra afm_sliding_reduced_a_si_mass_scaled
