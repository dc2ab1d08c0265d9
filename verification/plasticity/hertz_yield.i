# hertz_yield.i -- first yield under a Hertz contact (docs/theory.md 3.3; verification/plasticity/README.md):
# the coarse Hertz deck (verification/hertz/hertz_coarse.i: Si sphere R = 27 nm on a Si flat, 0.8 nm
# elements, fully integrated) with both bodies J2-plastic, Y = 4 GPa, K = 20 GPa, pushed to 230 ps.
#
# Run:    build/bin/tribex run verification/plasticity/hertz_yield.i -o hertz_yield_output
# Check:  /usr/bin/python3 verification/plasticity/compare_hertz_yield.py hertz_yield_output
# Quarter model (`symmetry = quarter`: x, y >= 0, the planes x = 0 and y = 0 held in x resp. y) with
# the mesh resolution, boundary conditions and driving of the full model it replaced (a quarter of its
# elements): forces and energies in history.csv are a quarter of the full problem's; the compare
# script reads that from the run's log.txt and multiplies by 4 (tools/python/history_checks.py).
#
# Expected (von Mises on the axis of the Hertz field, nu = 0.23): first yield when the Hertz peak
# pressure p0 = (6 P E*^2 / (pi^3 R^2))^(1/3) reaches 1.532 Y, at the depth 0.458 a below the surface,
# a = pi p0 R / (2 E*); until then the run is elastic (no plastic dissipation).
begin sierra hertz_yield
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0  0.00000
         10.0  0.00375
         20.0  0.01499
         30.0  0.03374
         40.0  0.05999
         50.0  0.08999
         60.0  0.11999
         70.0  0.14999
         80.0  0.17999
         90.0  0.20999
        100.0  0.23999
        110.0  0.26998
        120.0  0.29998
        130.0  0.32998
        140.0  0.35998
        150.0  0.38998
        160.0  0.42062
        170.0  0.45414
        180.0  0.49107
        190.0  0.53183
        200.0  0.57690
        210.0  0.62686
        220.0  0.68233
        230.0  0.74409
        240.0  0.81299
        250.0  0.89005
        260.0  0.97647
        270.0  1.07363
        280.0  1.18318
        290.0  1.30707
        300.0  1.44760
        310.0  1.60754
        315.2  1.70000
        335.2  1.70000
    end values
  end function push

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model j2_plasticity
      youngs modulus = 161 GPa
      poissons ratio = 0.23
      yield stress = 4 GPa
      hardening modulus = 20 GPa
    end parameters for model j2_plasticity
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
      model = j2_plasticity
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      model = j2_plasticity
      section = hex8
    end parameters for block substrate
  end finite element model asperity

  begin presto procedure indent
    begin time control
      termination time = 230 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
      quasi static = on             # run guards: kinetic energy below 5 % of internal energy while loaded
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
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 1 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex substrate_axis_top
      end history output hist
      begin results output fields
        time increment = 3 ps
        element variables = equivalent_plastic_strain
      end results output fields
    end presto region main
  end presto procedure indent
end sierra hertz_yield
