# mu0.1_h0.3_w0.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 0.1, element size 0.3 nm, W = 0 twin (frame compliance).
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu0.1_h0.3_w0.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu0.1
#
# Paraboloid tip R = 27 nm on a flat, both E = 94.71 GPa, nu = 0.23 (E* = 50 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap + delta: fast to 1.5 z0 above contact, then 4 m/s to the Hertz approach of 2 pi W_c R.
# Adhesive / element stiffness 16 W h/(E z0^2) = 0: time step scale factor 0.9/sqrt(1 + that).
begin sierra mu0.1_h0.3_w0
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
         150.0  5.59574
         155.0  5.74988
         160.0  5.83087
         165.0  5.84984
         170.0  5.85043
         175.0  5.85501
         180.0  5.86691
         185.0  5.88502
         190.0  5.90500
         195.0  5.92500
         200.0  5.94500
         205.0  5.96500
         210.0  5.98500
         215.0  6.00500
         220.0  6.02500
         225.0  6.04500
         230.0  6.06500
         235.0  6.08500
         240.0  6.10500
         245.0  6.12500
         250.0  6.14500
         255.0  6.16500
         260.0  6.18500
         265.0  6.20500
         270.0  6.22500
         275.0  6.24500
         280.0  6.26500
         285.0  6.28500
         290.0  6.30500
         295.0  6.32500
         300.0  6.34500
         305.0  6.36381
         310.0  6.37711
         315.0  6.38295
         319.7  6.38378
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
      element size = 0.3 nm
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
      termination time = 320 ps
      time step scale factor = 0.9
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
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 2 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
    end presto region main
  end presto procedure indent
end sierra mu0.1_h0.3_w0
