# limit_thick.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Limit h_c -> infinity: substrate of the coating material (f -> 1).
#
# Run:    build/bin/tribex run verification/coated/decks/limit_thick.i -o build/verification/coated_limit_thick
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 8 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.800 nm: 3 m/s, slowing to 0.25 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra limit_thick
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
          15.08  0.02740
          20.18  0.03340
          25.26  0.03620
          31.04  0.03780
          36.37  0.03920
          41.46  0.04060
          47.03  0.04220
          52.33  0.04380
          57.40  0.04540
          62.84  0.04720
          68.03  0.04900
          73.52  0.05100
          78.75  0.05300
          84.22  0.05520
          89.43  0.05740
          94.83  0.05980
          99.97  0.06220
         105.27  0.06480
         110.31  0.06740
         115.46  0.07020
         120.71  0.07320
         126.02  0.07640
         131.06  0.07960
         136.15  0.08300
         141.26  0.08660
         146.37  0.09040
         151.47  0.09440
         156.54  0.09860
         161.57  0.10300
         166.75  0.10780
         171.86  0.11280
         176.88  0.11800
         181.99  0.12360
         187.15  0.12960
         192.17  0.13580
         197.22  0.14240
         202.26  0.14940
         207.27  0.15680
         212.37  0.16480
         217.41  0.17320
         222.47  0.18220
         227.54  0.19180
         232.59  0.20200
         237.60  0.21280
         242.64  0.22440
         247.68  0.23680
         252.69  0.25000
         257.73  0.26420
         262.76  0.27940
         267.81  0.29580
         272.86  0.31340
         277.88  0.33220
         282.89  0.35240
         287.91  0.37420
         292.95  0.39780
         297.97  0.42320
         302.98  0.45060
         307.98  0.48020
         313.00  0.51240
         318.00  0.54720
         323.02  0.58520
         328.03  0.62640
         333.05  0.67140
         338.05  0.72020
         343.07  0.77040
         346.03  0.80000
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
      substrate width = 72 nm
      substrate depth = 36 nm
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
      material = coating
      section = hex8
    end parameters for block substrate
    begin parameters for block coating
      material = coating
      section = hex8
    end parameters for block coating
  end finite element model asperity

  begin presto procedure indent
    begin time control
      termination time = 347 ps
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
        time increment = 347 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra limit_thick
