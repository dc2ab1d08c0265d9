# case6.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 6, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case6.i -o build/verification/coated_case6
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 16 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.401 nm: 3 m/s, slowing to 0.65 m/s at 0.038 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra case6
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.00  0.00000
           2.50  0.00037
           5.00  0.00273
           7.50  0.00787
          10.00  0.01500
          15.01  0.02794
          20.02  0.03517
          25.09  0.03918
          30.22  0.04279
          35.31  0.04680
          40.32  0.05122
          45.39  0.05624
          50.44  0.06185
          55.48  0.06817
          60.50  0.07530
          65.55  0.08343
          70.59  0.09266
          75.62  0.10319
          80.64  0.11523
          85.66  0.12908
          90.66  0.14503
          95.69  0.16359
         100.70  0.18516
         105.70  0.21034
         110.72  0.24004
         115.73  0.27516
         120.73  0.31689
         125.74  0.36575
         129.30  0.40132
    end values
  end function push

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon

  begin property specification for material coating
    density = 1000 kg/m^3
    begin parameters for model elastic
      youngs modulus = 16 GPa
      poissons ratio = 0.4
    end parameters for model elastic
  end property specification for material coating

  # Fully integrated: penalty point forces excite the hourglass modes of one-point elements at the
  # surface (verification/hertz/README.md).
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8

  begin finite element model asperity
    begin generated asperity
      symmetry = quarter
      radius = 27 nm
      tip width = 12 nm
      tip height = 4 nm
      substrate width = 36 nm
      substrate depth = 18 nm
      element size = 0.4 nm
      fine half width = 5 nm
      fine depth = 1.2 nm
      grading ratio = 1.4
      coating thickness = 2 nm
      coating layers = 6
    end generated asperity
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
    begin parameters for block coating
      material = coating
      section = hex8
    end parameters for block coating
  end finite element model asperity

  begin presto procedure indent
    begin time control
      termination time = 130 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
      quasi static = on             # run guards: kinetic energy below 5 % of internal energy while loaded
      # Symmetry planes hold x (y); with them no rigid lateral motion or spin is left, so the
      # bottom is a roller (z) and the tip top is only driven in z (a node is constrained once).
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
      begin contact definition tip_on_coating
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        contact axis = 0 0 0 0 0 1 nm
        begin interaction sphere_flat
          surfaces = tip flat
        end interaction sphere_flat
      end contact definition tip_on_coating
      begin history output hist
        time increment = 1 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
      begin results output fields
        time increment = 130 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case6
