# diag_case4_rho250.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 4, element size 0.4 nm. Diagnostic of issue 52 (make_decks.py DIAGNOSTICS: {'case': 4, 'coating': (2.0, 6, 250.0)}).
#
# Run:    build/bin/tribex run verification/coated/decks/diag_case4_rho250.i -o build/verification/coated_diag_case4_rho250
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 2 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.615 nm: 3 m/s, slowing to 0.23 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra diag_case4_rho250
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
          15.06  0.02745
          20.07  0.03345
          25.24  0.03637
          30.27  0.03775
          35.38  0.03898
          40.90  0.04037
          46.19  0.04175
          51.26  0.04314
          56.66  0.04467
          61.83  0.04621
          67.28  0.04790
          72.49  0.04959
          77.93  0.05144
          83.13  0.05328
          88.51  0.05528
          93.66  0.05728
          98.96  0.05943
         104.02  0.06158
         109.21  0.06389
         114.49  0.06635
         119.53  0.06881
         124.64  0.07142
         129.81  0.07419
         135.01  0.07711
         140.22  0.08019
         145.43  0.08342
         150.62  0.08680
         155.79  0.09033
         160.92  0.09402
         166.00  0.09787
         171.03  0.10187
         176.17  0.10617
         181.23  0.11063
         186.37  0.11540
         191.40  0.12032
         196.47  0.12554
         201.56  0.13108
         206.65  0.13692
         211.72  0.14307
         216.76  0.14953
         221.86  0.15645
         226.90  0.16367
         231.97  0.17136
         237.03  0.17951
         242.08  0.18812
         247.10  0.19719
         252.15  0.20687
         257.21  0.21717
         262.25  0.22809
         267.25  0.23962
         272.27  0.25192
         277.28  0.26499
         282.31  0.27898
         287.33  0.29389
         292.38  0.30988
         297.42  0.32695
         302.42  0.34509
         307.46  0.36462
         312.49  0.38553
         317.49  0.40782
         322.50  0.43180
         327.52  0.45763
         332.53  0.48531
         337.53  0.51513
         342.54  0.54726
         347.55  0.58201
         351.97  0.61498
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
    density = 250 kg/m^3
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
      termination time = 352 ps
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
end sierra diag_case4_rho250
