# case5.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 5, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case5.i -o build/verification/coated_case5
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 4 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.844 nm: 3 m/s, slowing to 0.39 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 1 %: make_decks.py drive_times); bottom on rollers.
begin sierra case5
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
          15.10  0.02765
          20.17  0.03398
          25.34  0.03715
          30.58  0.03925
          35.96  0.04157
          40.99  0.04389
          46.10  0.04643
          51.26  0.04917
          56.43  0.05212
          61.58  0.05528
          66.68  0.05866
          71.71  0.06224
          76.92  0.06625
          82.00  0.07047
          87.16  0.07511
          92.36  0.08017
          97.54  0.08565
         102.68  0.09156
         107.75  0.09789
         112.87  0.10485
         117.99  0.11244
         123.07  0.12066
         128.08  0.12952
         133.09  0.13922
         138.17  0.14998
         143.24  0.16179
         148.27  0.17466
         153.28  0.18879
         158.30  0.20439
         163.32  0.22169
         168.36  0.24088
         173.39  0.26218
         178.41  0.28580
         183.43  0.31217
         188.45  0.34169
         193.48  0.37481
         198.50  0.41193
         203.50  0.45369
         208.52  0.50093
         213.54  0.55112
         218.56  0.60132
         223.58  0.65152
         228.60  0.70171
         233.61  0.75191
         238.63  0.80210
         242.79  0.84363
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
      termination time = 243 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
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
        time increment = 243 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case5
