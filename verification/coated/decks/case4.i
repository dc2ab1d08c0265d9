# case4.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 4, element size 0.4 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case4.i -o build/verification/coated_case4
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 2 GPa, nu_c = 0.4, h_c = 2 nm in 6 layers. R = 27 nm.
# Tip top pushed 0.922 nm: 3 m/s, slowing to 0.28 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 1 %: make_decks.py drive_times); bottom on rollers.
begin sierra case4
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
          15.04  0.02745
          20.20  0.03368
          25.51  0.03668
          30.93  0.03829
          36.42  0.03991
          41.63  0.04152
          47.29  0.04337
          52.65  0.04521
          57.75  0.04706
          63.19  0.04913
          68.36  0.05121
          73.79  0.05351
          78.95  0.05582
          84.32  0.05836
          89.40  0.06089
          94.66  0.06366
         100.04  0.06666
         105.12  0.06966
         110.30  0.07288
         115.54  0.07634
         120.81  0.08003
         126.09  0.08395
         131.36  0.08811
         136.59  0.09249
         141.77  0.09710
         146.88  0.10194
         151.93  0.10702
         157.10  0.11255
         162.17  0.11832
         167.30  0.12454
         172.46  0.13123
         177.47  0.13815
         182.48  0.14553
         187.61  0.15360
         192.67  0.16213
         197.79  0.17136
         202.80  0.18104
         207.81  0.19142
         212.90  0.20272
         217.92  0.21471
         222.95  0.22763
         227.96  0.24147
         233.00  0.25646
         238.02  0.27260
         243.08  0.29013
         248.12  0.30904
         253.17  0.32956
         258.20  0.35170
         263.22  0.37569
         268.23  0.40175
         273.25  0.43011
         278.27  0.46101
         283.27  0.49468
         288.30  0.53158
         293.31  0.57194
         298.33  0.61622
         303.33  0.66465
         308.33  0.71469
         313.34  0.76474
         318.34  0.81478
         323.35  0.86482
         328.35  0.91487
         329.11  0.92247
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
      termination time = 330 ps
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
        time increment = 330 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case4
