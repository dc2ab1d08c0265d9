# case1_h0.4.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 1, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case1_h0.4.i -o build/verification/coated_case1_h0.4
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 8 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.784 nm at 3 m/s after a 20 ps cycloidal start; bottom on rollers.
begin sierra case1_h0.4
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.00  0.00000
           2.50  0.00010
           5.00  0.00075
           7.50  0.00243
          10.00  0.00545
          12.50  0.00993
          15.00  0.01575
          17.50  0.02260
          20.00  0.03000
          30.00  0.06000
          40.00  0.09000
          50.00  0.12000
          60.00  0.15000
          70.00  0.18000
          80.00  0.21000
          90.00  0.24000
         100.00  0.27000
         110.00  0.30000
         120.00  0.33000
         130.00  0.36000
         140.00  0.39000
         150.00  0.42000
         160.00  0.45000
         170.00  0.48000
         180.00  0.51000
         190.00  0.54000
         200.00  0.57000
         210.00  0.60000
         220.00  0.63000
         230.00  0.66000
         240.00  0.69000
         250.00  0.72000
         260.00  0.75000
         270.00  0.78000
         271.20  0.78360
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
      tip width = 14 nm
      tip height = 6 nm
      substrate width = 60 nm
      substrate depth = 30 nm
      element size = 0.4 nm
      fine half width = 5 nm
      fine depth = 2.5 nm
      grading ratio = 1.3
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
      termination time = 272 ps
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
        time increment = 272 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case1_h0.4
