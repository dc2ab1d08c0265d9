# hertz_rescaled.i -- hertz_coarse.i rescaled: another sphere radius and other moduli on the same
# coarse mesh scaled by 1.5 (same element counts), to measure the contact-radius estimators away from
# the deck they were developed on (verification/hertz/README.md, "The contact-radius estimators").
#
# Every length of hertz_coarse.i times s = 1.5 (R = 40.5 nm, element size 1.2 nm); E = 100 GPa and
# nu = 0.3 (E* = 54.9 GPa); every time (the push, the history interval, the end) times
# tau = s sqrt(161/100) = 1.90329, so that the loading rate is the same fraction of the wave speed;
# the mass damping over tau. No results output.
#
# Run:    build/bin/tribex run verification/hertz/hertz_rescaled.i -o hertz_rescaled_output
# Check:  /usr/bin/python3 verification/hertz/compare.py hertz_rescaled_output --element-size 1.2 \
#             --tip-radius 40.5 --youngs-modulus 100 --poissons-ratio 0.3
begin sierra hertz_rescaled
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.000  0.00000
          19.033  0.00562
          38.066  0.02248
          57.099  0.05061
          76.131  0.08999
          95.164  0.13498
         114.197  0.17999
         133.230  0.22499
         152.263  0.26999
         171.296  0.31499
         190.329  0.35998
         209.362  0.40497
         228.394  0.44997
         247.427  0.49497
         266.460  0.53997
         285.493  0.58497
         304.526  0.63093
         323.559  0.68121
         342.592  0.73660
         361.624  0.79775
         380.657  0.86535
         399.690  0.94029
         418.723  1.02350
         437.756  1.11614
         456.789  1.21948
         475.822  1.33508
         494.855  1.46470
         513.887  1.61045
         532.920  1.77477
         551.953  1.96060
         570.986  2.17140
         590.019  2.41131
         599.916  2.55000
         637.982  2.55000
    end values
  end function push

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 100 GPa
      poissons ratio = 0.3
    end parameters for model elastic
  end property specification for material silicon

  # Fully integrated: the concentrated penalty forces of node-to-face contact excite the hourglass
  # modes of one-point (mean-quadrature) elements at the surface; at these contact pressures
  # (p0 up to 14 GPa) that coupling pumped energy into the contact and inverted elements.
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8

  begin finite element model asperity
    begin generated asperity
      radius = 40.5 nm
      tip width = 48 nm
      tip height = 39 nm
      substrate width = 180 nm
      substrate depth = 90 nm
      element size = 1.2 nm
      fine half width = 10.8 nm
      fine depth = 4.8 nm
      grading ratio = 1.35
    end generated asperity
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
  end finite element model asperity

  begin presto procedure indent
    begin time control
      termination time = 656.63 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 2.627e+11 1/s
      quasi static = on             # run guards: kinetic energy below 5 % of internal energy while loaded
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = tip_top
        components = x y
      end fixed displacement
      begin prescribed displacement
        node set = tip_top
        component = z
        function = push
        scale factor = -1
      end prescribed displacement
      begin contact definition tip_on_flat
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        contact axis = 0 0 0 0 0 1 nm
        begin interaction sphere_flat
          surfaces = tip flat
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 5.7099 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
    end presto region main
  end presto procedure indent
end sierra hertz_rescaled
