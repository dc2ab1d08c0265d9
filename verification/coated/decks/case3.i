# case3.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 3, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case3.i -o build/verification/coated_case3
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 8 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 35 nm.
# Tip top pushed 0.777 nm: 3 m/s, slowing to 0.52 m/s at 0.034 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 1 %: make_decks.py drive_times); bottom on rollers.
begin sierra case3
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
          15.01  0.02666
          20.26  0.03249
          25.33  0.03540
          30.43  0.03832
          35.66  0.04162
          40.91  0.04531
          46.14  0.04939
          51.27  0.05386
          56.28  0.05872
          61.30  0.06416
          66.44  0.07038
          71.44  0.07718
          76.52  0.08495
          81.58  0.09369
          86.65  0.10360
          91.72  0.11487
          96.79  0.12770
         101.82  0.14227
         106.86  0.15898
         111.90  0.17822
         116.92  0.20037
         121.92  0.22602
         126.94  0.25594
         131.94  0.29091
         136.95  0.33211
         141.95  0.38030
         146.97  0.43043
         151.98  0.48056
         156.99  0.53069
         162.01  0.58082
         167.02  0.63095
         172.03  0.68108
         177.05  0.73121
         181.65  0.77722
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
      radius = 35 nm
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
      termination time = 182 ps
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
        time increment = 182 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case3
