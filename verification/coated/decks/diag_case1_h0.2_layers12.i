# diag_case1_h0.2_layers12.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 1, element size 0.2 nm. Diagnostic of issue 52 (make_decks.py DIAGNOSTICS: {'h': 0.2, 'fit_start': (0.025, 0.35), 'coating': (2.0, 12, 1000.0)}).
#
# Run:    build/bin/tribex run verification/coated/decks/diag_case1_h0.2_layers12.i -o build/verification/coated_diag_case1_h0.2_layers12
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 8 GPa, nu_c = 0.4, h_c = 2 nm in 12 layers. R = 27 nm.
# Tip top pushed 0.490 nm: 3 m/s, slowing to 0.35 m/s at 0.025 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra diag_case1_h0.2_layers12
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
          15.12  0.02271
          20.37  0.02541
          25.60  0.02737
          30.68  0.02945
          35.84  0.03177
          41.03  0.03435
          46.17  0.03716
          51.24  0.04022
          56.38  0.04365
          61.51  0.04745
          66.57  0.05161
          71.66  0.05626
          76.70  0.06140
          81.76  0.06716
          86.85  0.07365
          91.89  0.08087
          96.90  0.08895
         101.95  0.09814
         107.00  0.10854
         112.02  0.12030
         117.03  0.13364
         122.05  0.14895
         127.07  0.16646
         132.09  0.18666
         137.09  0.20992
         142.10  0.23698
         147.12  0.26857
         152.12  0.30555
         157.13  0.34913
         162.14  0.39872
         167.15  0.44880
         171.24  0.48975
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
      termination time = 172 ps
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
end sierra diag_case1_h0.2_layers12
