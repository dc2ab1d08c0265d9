# case4_h0.2.i -- coated-substrate study (verification/coated/README.md), written by make_decks.py: edit
# the generator, not this file. Table B.1 case 4, element size 0.2 nm.
#
# Run:    build/bin/tribex run verification/coated/decks/case4_h0.2.i -o build/verification/coated_case4_h0.2
# Check:  /usr/bin/python3 verification/coated/study.py (reads every run folder present)
#
# Quarter model (x, y >= 0; symmetry_x / symmetry_y hold x / y): forces and areas in history.csv
# are a quarter of the full problem's; study.py multiplies by 4. Tip and substrate: E = 161 GPa,
# nu = 0.23; coating: E_c = 2 GPa, nu_c = 0.4, h_c = 2 nm in 12 layers. R = 27 nm.
# Tip top pushed 0.615 nm: 3 m/s, slowing to 0.17 m/s at 0.037 nm (first fitted load), then
# v ~ travel^1.25 up to 10 m/s (KE/IE about 0.7 %: make_decks.py drive_times); bottom on rollers.
begin sierra case4_h0.2
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
          15.00  0.02730
          20.07  0.03330
          25.11  0.03606
          30.67  0.03745
          35.86  0.03837
          40.90  0.03929
          46.59  0.04037
          52.09  0.04144
          57.42  0.04252
          62.59  0.04360
          67.60  0.04467
          73.14  0.04590
          78.50  0.04713
          83.68  0.04836
          88.71  0.04959
          94.18  0.05098
          99.47  0.05236
         104.58  0.05374
         110.07  0.05528
         115.38  0.05682
         120.51  0.05836
         125.96  0.06005
         131.22  0.06174
         136.31  0.06343
         141.67  0.06527
         146.84  0.06712
         152.25  0.06912
         157.46  0.07112
         162.49  0.07312
         167.73  0.07527
         172.77  0.07742
         177.99  0.07973
         183.02  0.08203
         188.20  0.08449
         193.50  0.08711
         198.60  0.08972
         203.81  0.09249
         208.82  0.09525
         213.92  0.09818
         219.08  0.10125
         224.30  0.10448
         229.32  0.10771
         234.38  0.11109
         239.47  0.11463
         244.57  0.11832
         249.68  0.12216
         254.79  0.12616
         259.88  0.13031
         264.95  0.13461
         269.99  0.13907
         275.00  0.14368
         280.13  0.14860
         285.19  0.15368
         290.20  0.15891
         295.28  0.16444
         300.29  0.17013
         305.34  0.17612
         310.43  0.18243
         315.53  0.18904
         320.64  0.19596
         325.74  0.20318
         330.82  0.21072
         335.87  0.21856
         340.89  0.22671
         345.95  0.23532
         350.95  0.24423
         355.97  0.25361
         361.00  0.26345
         366.01  0.27375
         371.07  0.28467
         376.10  0.29605
         381.14  0.30804
         386.18  0.32064
         391.21  0.33387
         396.21  0.34770
         401.23  0.36231
         406.25  0.37768
         411.29  0.39398
         416.30  0.41105
         421.31  0.42903
         426.34  0.44810
         431.37  0.46824
         436.38  0.48946
         441.40  0.51190
         446.40  0.53558
         451.40  0.56064
         456.42  0.58724
         461.35  0.61498
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
      termination time = 462 ps
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
        time increment = 462 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra case4_h0.2
