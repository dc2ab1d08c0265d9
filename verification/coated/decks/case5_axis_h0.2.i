# case5_axis_h0.2.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 5, element size 0.2 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case5_axis_h0.2.i -o build/verification/coated_case5_axis_h0.2
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 4 GPa, nu_c = 0.4, h_c = 2 nm in 12 layers. R = 27 nm.
# Tip top pushed 0.562 nm: 3 m/s, slowing to 0.24 m/s at 0.025 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra case5_axis_h0.2
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
          15.04  0.02245
          20.37  0.02498
          25.39  0.02625
          30.62  0.02765
          36.00  0.02920
          41.03  0.03075
          46.18  0.03243
          51.38  0.03426
          56.62  0.03623
          61.85  0.03834
          67.04  0.04059
          72.18  0.04298
          77.24  0.04551
          82.47  0.04832
          87.57  0.05128
          92.74  0.05451
          97.75  0.05788
         102.78  0.06154
         107.80  0.06548
         112.93  0.06984
         117.97  0.07448
         123.03  0.07954
         128.09  0.08502
         133.09  0.09093
         138.13  0.09739
         143.15  0.10442
         148.21  0.11216
         153.25  0.12059
         158.31  0.12987
         163.33  0.14000
         168.35  0.15111
         173.37  0.16334
         178.39  0.17684
         183.41  0.19174
         188.44  0.20833
         193.44  0.22661
         198.46  0.24700
         203.48  0.26978
         208.50  0.29522
         213.50  0.32363
         218.51  0.35554
         223.52  0.39154
         228.52  0.43217
         233.53  0.47829
         238.55  0.52835
         241.95  0.56242
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
      youngs modulus = 4 GPa
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
      element size = 0.2 nm
      fine half width = 5 nm
      fine depth = 1.2 nm
      grading ratio = 1.4
      coating thickness = 2 nm
      coating layers = 12
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
      termination time = 242 ps
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
        penalty scale factor = 0.55
        begin interaction sphere_flat
          surfaces = tip flat
          force direction = axis
        end interaction sphere_flat
      end contact definition tip_on_coating
      begin history output hist
        time increment = 1 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
      begin results output fields
        time increment = 242 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case5_axis_h0.2
