# case7.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 7, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case7.i -o build/verification/coated_case7
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 322 GPa,
# nu = 0.23; coating: E_c = 16 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.735 nm: 3 m/s, slowing to 0.77 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 1 %: make_decks.py drive_times); bottom on rollers.
begin sierra case7
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
          15.04  0.02786
          20.04  0.03502
          25.23  0.03943
          30.23  0.04383
          35.33  0.04898
          40.39  0.05485
          45.46  0.06165
          50.53  0.06955
          55.60  0.07873
          60.63  0.08938
          65.64  0.10187
          70.70  0.11675
          75.73  0.13438
          80.74  0.15531
          85.74  0.18048
          90.74  0.21096
          95.76  0.24824
         100.76  0.29398
         105.77  0.34411
         110.79  0.39425
         115.80  0.44439
         120.81  0.49453
         125.83  0.54467
         130.84  0.59481
         135.86  0.64494
         140.87  0.69508
         144.82  0.73463
    end values
  end function push

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 322 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon

  begin property specification for material coating
    density = 1000 kg/m^3
    begin parameters for model elastic
      youngs modulus = 16 GPa
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
      termination time = 145 ps
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
        time increment = 145 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case7
