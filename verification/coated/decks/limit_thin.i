# limit_thin.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Limit h_c -> 0: a 0.02 nm coating (f -> (2/(1 + Ebar/Ebar_c))^(2/3)), coating density scaled to 137,500 kg/m^3 (mass scaling, KE/IE checked).
#
# Run:    build/bin/tribex run verification/coated/decks/limit_thin.i -o build/verification/coated_limit_thin
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 8 GPa, nu_c = 0.4, h_c = 0.02 nm in 1 layers. R = 27 nm.
# Tip top pushed 0.800 nm: 3 m/s, slowing to 1.50 m/s at 0.150 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra limit_thin
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
          15.07  0.03020
          20.13  0.04540
          25.20  0.06060
          30.20  0.07560
          35.27  0.09000
          40.33  0.10300
          45.42  0.11480
          50.47  0.12540
          55.54  0.13500
          60.56  0.14360
          65.59  0.15140
          70.69  0.15940
          75.72  0.16780
          80.76  0.17680
          85.80  0.18640
          90.82  0.19660
          95.87  0.20760
         100.93  0.21940
         105.97  0.23200
         110.97  0.24540
         115.98  0.25980
         121.03  0.27540
         126.08  0.29220
         131.10  0.31020
         136.12  0.32960
         141.15  0.35060
         146.17  0.37320
         151.17  0.39760
         156.20  0.42420
         161.23  0.45300
         166.24  0.48420
         171.26  0.51820
         176.27  0.55520
         181.29  0.59560
         186.30  0.63960
         191.31  0.68780
         196.31  0.73780
         201.31  0.78780
         202.53  0.80000
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
    density = 137500 kg/m^3
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
      fine half width = 5.5 nm
      fine depth = 1.2 nm
      grading ratio = 1.4
      coating thickness = 0.02 nm
      coating layers = 1
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
      termination time = 203 ps
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
        time increment = 203 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra limit_thin
