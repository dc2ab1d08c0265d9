# diag_case1_slow2.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 1, element size 0.4 nm. Diagnostic of issue 52 (make_decks.py DIAGNOSTICS: {'slow': 2.0}).
#
# Run:    build/bin/tribex run verification/coated/decks/diag_case1_slow2.i -o build/verification/coated_diag_case1_slow2
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 8 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.490 nm: 3 m/s, slowing to 0.46 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra diag_case1_slow2
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.00  0.00000
           2.50  0.00005
           5.00  0.00037
           7.50  0.00121
          10.00  0.00273
          12.50  0.00496
          15.00  0.00787
          17.50  0.01130
          20.00  0.01500
          25.03  0.02222
          30.10  0.02761
          35.13  0.03141
          40.17  0.03410
          45.36  0.03606
          50.42  0.03741
          55.67  0.03863
          60.72  0.03985
          66.06  0.04120
          71.18  0.04255
          76.54  0.04402
          81.69  0.04549
          87.03  0.04708
          92.15  0.04867
          97.43  0.05038
         102.50  0.05210
         107.70  0.05394
         113.01  0.05589
         118.09  0.05785
         123.26  0.05993
         128.49  0.06214
         133.50  0.06434
         138.56  0.06667
         143.65  0.06912
         148.76  0.07169
         153.87  0.07438
         158.97  0.07720
         164.05  0.08014
         169.10  0.08320
         174.12  0.08638
         179.26  0.08981
         184.34  0.09336
         189.34  0.09703
         194.43  0.10095
         199.57  0.10511
         204.60  0.10940
         209.65  0.11393
         214.72  0.11871
         219.78  0.12373
         224.81  0.12899
         229.81  0.13450
         234.87  0.14038
         239.97  0.14662
         244.98  0.15311
         250.00  0.15997
         255.00  0.16719
         260.05  0.17490
         265.06  0.18299
         270.07  0.19156
         275.07  0.20062
         280.11  0.21029
         285.16  0.22057
         290.20  0.23147
         295.21  0.24298
         300.22  0.25522
         305.26  0.26832
         310.26  0.28216
         315.29  0.29698
         320.31  0.31277
         325.35  0.32967
         330.37  0.34766
         335.38  0.36689
         340.40  0.38746
         345.41  0.40950
         350.43  0.43313
         355.45  0.45810
         360.47  0.48320
         361.78  0.48975
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
      youngs modulus = 8 GPa
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
      termination time = 362 ps
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
        time increment = 2 ps
        nodal variables = displacement contact_traction contact_status gap contact_pressure
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra diag_case1_slow2
