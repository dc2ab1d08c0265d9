# dmt_coarse_mass_scaled.i -- dmt_coarse.i with selective mass scaling
# (begin mass scaling, docs/theory.md 1.4.1): every element whose stable step is below twice the
# smallest gets its density raised to reach it. Otherwise the deck is dmt_coarse.i line for line (same mesh,
# driving, outputs); the compare script checks it with the unscaled deck's tolerance (verification/dmt/README.md, "Mass scaling").
#
# dmt_coarse.i -- DMT adhesive contact of a silicon sphere (R = 27 nm) on a silicon flat: the Hertz
# problem of verification/hertz with the Lennard-Jones adhesion model (W = 0.05 J/m^2, z0 = 0.3 nm,
# Tabor parameter mu_T = 0.070 < 0.1: the DMT limit), loaded to 1.1 nm, then withdrawn past pull-off.
#
# Run:    build/bin/tribex run verification/dmt/dmt_coarse_mass_scaled.i -o dmt_coarse_mass_scaled_output
# Check:  /usr/bin/python3 verification/dmt/compare.py dmt_coarse_mass_scaled_output --element-size 0.8
# Quarter model (`symmetry = quarter`: x, y >= 0, the planes x = 0 and y = 0 held in x resp. y) with
# the mesh resolution, boundary conditions and driving of the full model it replaced (a quarter of its
# elements): forces, areas and energies in history.csv are a quarter of the full problem's; the compare
# scripts read that from the run's log.txt and multiply by 4 (tools/python/history_checks.py).
#
# Same mesh, material and driving as verification/hertz/hertz_coarse.i (see its sketch); the tip top
# is pushed down 1.1 nm, held 10 ps, then pulled up at 4 m/s until the apex is 0.8 nm above contact.
begin sierra dmt_coarse_mass_scaled
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0  0.00000
          6.0  0.00135
         12.0  0.00540
         18.0  0.01214
         24.0  0.02159
         30.0  0.03374
         36.0  0.04859
         42.0  0.06599
         48.0  0.08399
         54.0  0.10199
         60.0  0.11999
         66.0  0.13799
         72.0  0.15599
         78.0  0.17399
         84.0  0.19199
         90.0  0.20999
         96.0  0.22799
        102.0  0.24599
        108.0  0.26399
        114.0  0.28198
        120.0  0.29998
        126.0  0.31798
        132.0  0.33598
        138.0  0.35398
        144.0  0.37198
        150.0  0.38998
        156.0  0.40809
        162.0  0.42707
        168.0  0.44718
        174.0  0.46848
        180.0  0.49107
        186.0  0.51504
        192.0  0.54048
        198.0  0.56752
        204.0  0.59626
        210.0  0.62686
        216.0  0.65943
        222.0  0.69416
        228.0  0.73119
        234.0  0.77074
        240.0  0.81299
        246.0  0.85817
        252.0  0.90654
        258.0  0.95837
        264.0  1.01395
        270.0  1.07363
        272.5  1.10000
        282.5  1.10000
        757.5  -0.80000
    end values
  end function push

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
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
      symmetry = quarter
      radius = 27 nm
      tip width = 32 nm
      tip height = 26 nm
      substrate width = 120 nm
      substrate depth = 60 nm
      element size = 0.8 nm
      fine half width = 7.2 nm
      fine depth = 3.2 nm
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
      termination time = 757 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
      quasi static = on             # run guards: kinetic energy below 5 % of internal energy while loaded
      begin mass scaling
        largest factor = 2                  # target time step = 2 x the unscaled step
        maximum added mass fraction = 0.05  # stop (exit 3) above 5 % added mass
        maximum kinetic energy ratio = 0.1  # stop (exit 3) when KE > 10 % of IE while loaded
      end mass scaling
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = tip_top
        components = x y
      end fixed displacement
      # Symmetry planes of the quarter model. Where they meet the fixed bottom and the tip top (held in x
      # and y) a component is fixed twice, which a fixed displacement allows: on its quarter these are
      # exactly the full model's conditions.
      begin fixed displacement
        node set = symmetry_x
        components = x
      end fixed displacement
      begin fixed displacement
        node set = symmetry_y
        components = y
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
          model = adhesion
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm      # 20 z0: the law keeps 99 % of W (docs/theory.md 6.3)
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 3 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
      begin results output fields
        time increment = 15 ps
        nodal variables = displacement contact_traction contact_status
        element variables = stress
      end results output fields
    end presto region main
  end presto procedure indent
end sierra dmt_coarse_mass_scaled
