# diag_case4_h0.3_pen0.25.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 4, element size 0.3 nm. Diagnostic of issue 52 (make_decks.py DIAGNOSTICS: {'case': 4, 'h': 0.3, 'fit_start': (0.025, 0.17436241149923226), 'penalty': 0.25}).
#
# Run:    build/bin/tribex run verification/coated/decks/diag_case4_h0.3_pen0.25.i -o build/verification/coated_diag_case4_h0.3_pen0.25
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 2 GPa, nu_c = 0.4, h_c = 2 nm in 8 layers. R = 27 nm.
# Tip top pushed 0.615 nm: 3 m/s, slowing to 0.17 m/s at 0.025 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra diag_case4_h0.3_pen0.25
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
          15.11  0.02238
          20.15  0.02469
          25.95  0.02576
          31.74  0.02684
          37.25  0.02791
          42.50  0.02899
          47.52  0.03007
          52.98  0.03130
          58.18  0.03253
          63.74  0.03391
          69.03  0.03529
          74.06  0.03668
          79.39  0.03822
          84.45  0.03975
          89.74  0.04144
          94.77  0.04314
          99.98  0.04498
         105.33  0.04698
         110.41  0.04898
         115.59  0.05113
         120.85  0.05344
         126.16  0.05590
         131.18  0.05836
         136.24  0.06097
         141.30  0.06374
         146.36  0.06666
         151.39  0.06973
         156.61  0.07312
         161.76  0.07665
         166.83  0.08034
         171.99  0.08434
         177.05  0.08849
         182.15  0.09295
         187.29  0.09771
         192.41  0.10279
         197.52  0.10817
         202.58  0.11386
         207.59  0.11985
         212.64  0.12631
         217.70  0.13323
         222.76  0.14061
         227.78  0.14845
         232.83  0.15691
         237.89  0.16598
         242.92  0.17566
         247.97  0.18612
         253.02  0.19734
         258.02  0.20933
         263.03  0.22225
         268.06  0.23624
         273.08  0.25131
         278.10  0.26760
         283.13  0.28528
         288.14  0.30435
         293.16  0.32510
         298.19  0.34770
         303.19  0.37215
         308.22  0.39890
         313.22  0.42796
         318.23  0.45978
         323.25  0.49468
         328.25  0.53281
         333.26  0.57479
         337.65  0.61498
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
      youngs modulus = 2 GPa
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
      element size = 0.3 nm
      fine half width = 5 nm
      fine depth = 1.2 nm
      grading ratio = 1.4
      coating thickness = 2 nm
      coating layers = 8
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
      termination time = 338 ps
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
        penalty scale factor = 0.25
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
end sierra diag_case4_h0.3_pen0.25
