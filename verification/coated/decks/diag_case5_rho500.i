# diag_case5_rho500.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 5, element size 0.4 nm. Diagnostic of issue 52 (make_decks.py DIAGNOSTICS: {'case': 5, 'coating': (2.0, 6, 500.0)}).
#
# Run:    build/bin/tribex run verification/coated/decks/diag_case5_rho500.i -o build/verification/coated_diag_case5_rho500
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 4 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.562 nm: 3 m/s, slowing to 0.33 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra diag_case5_rho500
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
          15.05  0.02751
          20.22  0.03384
          25.22  0.03679
          30.57  0.03862
          35.78  0.04045
          41.07  0.04242
          46.42  0.04453
          51.45  0.04664
          56.51  0.04889
          61.59  0.05128
          66.64  0.05381
          71.67  0.05648
          76.89  0.05943
          82.02  0.06252
          87.06  0.06576
          92.19  0.06927
          97.20  0.07293
         102.25  0.07687
         107.32  0.08108
         112.37  0.08558
         117.38  0.09036
         122.48  0.09557
         127.49  0.10105
         132.51  0.10696
         137.53  0.11328
         142.61  0.12017
         147.61  0.12748
         152.61  0.13536
         157.66  0.14393
         162.72  0.15321
         167.75  0.16320
         172.79  0.17402
         177.80  0.18569
         182.81  0.19835
         187.82  0.21213
         192.85  0.22717
         197.86  0.24348
         202.88  0.26134
         207.90  0.28088
         212.92  0.30225
         217.94  0.32574
         222.95  0.35147
         227.97  0.37987
         232.98  0.41108
         237.98  0.44553
         242.99  0.48378
         248.00  0.52610
         251.90  0.56242
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
    density = 500 kg/m^3
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
      termination time = 252 ps
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
end sierra diag_case5_rho500
