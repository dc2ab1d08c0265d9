# case5_h0.2.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 5, element size 0.2 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case5_h0.2.i -o build/verification/coated_case5_h0.2
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 4 GPa, nu_c = 0.4, h_c = 2 nm in 12 layers. R = 27 nm.
# Tip top pushed 0.562 nm: 3 m/s, slowing to 0.24 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra case5_h0.2
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
          15.01  0.02737
          20.16  0.03356
          25.47  0.03651
          30.56  0.03792
          36.07  0.03932
          41.33  0.04073
          46.37  0.04214
          51.68  0.04368
          56.76  0.04523
          62.05  0.04692
          67.12  0.04860
          72.36  0.05043
          77.37  0.05226
          82.53  0.05423
          87.80  0.05634
          92.84  0.05845
          97.96  0.06070
         103.15  0.06309
         108.38  0.06562
         113.64  0.06829
         118.65  0.07096
         123.67  0.07377
         128.69  0.07673
         133.70  0.07982
         138.89  0.08319
         144.03  0.08671
         149.10  0.09036
         154.10  0.09416
         159.20  0.09824
         164.21  0.10246
         169.27  0.10696
         174.37  0.11174
         179.48  0.11680
         184.57  0.12214
         189.65  0.12776
         194.68  0.13367
         199.78  0.14000
         204.80  0.14661
         209.85  0.15364
         214.89  0.16109
         219.90  0.16896
         224.96  0.17740
         229.96  0.18626
         234.97  0.19568
         240.02  0.20580
         245.02  0.21649
         250.03  0.22788
         255.06  0.24011
         260.11  0.25318
         265.13  0.26710
         270.16  0.28201
         275.16  0.29790
         280.16  0.31491
         285.18  0.33319
         290.20  0.35287
         295.21  0.37396
         300.24  0.39674
         305.26  0.42121
         310.28  0.44764
         315.28  0.47604
         320.30  0.50683
         325.32  0.54016
         328.46  0.56242
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
      termination time = 329 ps
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
        time increment = 329 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case5_h0.2
