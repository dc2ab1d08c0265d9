# mu1_h0.5_w0.i -- adhesion across the Tabor range (verification/adhesion_transition/README.md), written by
# make_decks.py: edit the generator, not this file. mu_T = 1, element size 0.5 nm, W = 0 twin (frame compliance).
#
# Run:    build/bin/tribex run verification/adhesion_transition/decks/mu1_h0.5_w0.i -o OUT
# Check:  /usr/bin/python3 verification/adhesion_transition/compare.py OUT --twin OUT_W0 --reference
#         verification/adhesion_transition/reference/mu1
#
# Paraboloid tip R = 27 nm on a flat, both E = 2.995 GPa, nu = 0.23 (E* = 1.5811 GPa), density scaled to
# keep silicon's wave speed. Quarter model: forces in history.csv are a quarter of the full problem's.
# Push (nm) = gap + delta: fast to 1.5 z0 above contact, then 16 m/s to the Hertz approach of 1 pi W_c R.
# Adhesive / element stiffness 16 W h/(E z0^2) = 0: time step scale factor 0.9/sqrt(1 + that).
begin sierra mu1_h0.5_w0
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
          70.0  4.80000
          75.0  5.19892
          80.0  5.54958
          85.0  5.76868
          90.0  5.84504
          95.0  5.85022
         100.0  5.86008
         105.0  5.89626
         110.0  5.96099
         115.0  6.04000
         120.0  6.12000
         125.0  6.20000
         130.0  6.28000
         135.0  6.36000
         140.0  6.44000
         145.0  6.52000
         150.0  6.60000
         155.0  6.67999
         160.0  6.75395
         165.0  6.80445
         170.0  6.82533
         174.2  6.82778
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
      termination time = 175 ps
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
end sierra mu1_h0.5_w0
