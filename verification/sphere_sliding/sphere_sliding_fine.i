# sphere_sliding_fine.i -- written by make_decks.py (edit that, not this file).
# A silicon sphere (R = 27 nm) indented into a silicon flat, held, then slid tangentially with the
# junction model (issue 4 acceptance): W = 0.05 J/m^2, z0 = 0.3 nm (as verification/dmt), tau* = 195 MPa.
#
# Run:    build/bin/tribex run verification/sphere_sliding/sphere_sliding_fine.i -o sphere_sliding_fine_output
# Check:  /usr/bin/python3 verification/sphere_sliding/compare.py sphere_sliding_fine_output --window 0.4 2.4
#
# Procedure (one deck, one time line; the two stages are functions of time on the tip top):
#   0 - 130 ps   indent: tip top pushed down 0.72 nm (cycloidal ramps, 8.0 m/s)
#   130 - 150 ps  hold: displacement hold of the tip top (not load control: the tip
#                     top's z stays prescribed; the normal load is the contact normal force,
#                     measured, and it drifts by about 1 % while sliding: tau* is 2 % of the
#                     mean contact pressure)
#   150 - 410 ps  slide in +x at 10.0 m/s (2.40 nm), the z hold kept.
# Expected in steady sliding: friction = tau* pi a^2, a = DMT radius at the contact normal force P,
#   a^3 = 3 R (P + 2 pi W R) / (4 E*), E* = E / (2 (1 - nu^2)) = 85.0 GPa.
# In contact: where the gap interpolated over the tip-surface faces is <= 0 (junction gap tolerance
# = 0: with penalty contact the constraint is active for g < 0; the default g_j = 0.05 z0 would add
# the annulus where the Hertz gap is below 0.015 nm, about 0.45 nm wide here, +20 % area); the shear
# acts on each node's share of that area (contact/models/README.md).
# Quasi-static: mass damping 5e11 1/s (about half critical for the column's axial mode, as in
# verification/hertz); compare.py checks kinetic / internal energy below 2 % in the steady window. The
# damping drags the sliding tip (c M V); the driver carries it, the interface shear does not.
begin sierra sphere_sliding_fine
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0  0.00000
          5.0  0.00051
         10.0  0.00399
         15.0  0.01295
         20.0  0.02907
         25.0  0.05295
         30.0  0.08399
         35.0  0.12051
         40.0  0.16000
         45.0  0.20000
         50.0  0.24000
         55.0  0.28000
         60.0  0.32000
         65.0  0.36000
         70.0  0.40000
         75.0  0.44000
         80.0  0.48000
         85.0  0.52000
         90.0  0.56000
         95.0  0.59949
        100.0  0.63601
        105.0  0.66705
        110.0  0.69093
        115.0  0.70705
        120.0  0.71601
        125.0  0.71949
        130.0  0.72000
    410.0  0.72000
    end values
  end function push
  begin function slide
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0  0.00000
        150.0  0.00000
        155.0  0.00064
        160.0  0.00498
        165.0  0.01618
        170.0  0.03634
        175.0  0.06618
        180.0  0.10498
        185.0  0.15064
        190.0  0.20000
        195.0  0.25000
        200.0  0.30000
        205.0  0.35000
        210.0  0.40000
        215.0  0.45000
        220.0  0.50000
        225.0  0.55000
        230.0  0.60000
        235.0  0.65000
        240.0  0.70000
        245.0  0.75000
        250.0  0.80000
        255.0  0.85000
        260.0  0.90000
        265.0  0.95000
        270.0  1.00000
        275.0  1.05000
        280.0  1.10000
        285.0  1.15000
        290.0  1.20000
        295.0  1.25000
        300.0  1.30000
        305.0  1.35000
        310.0  1.40000
        315.0  1.45000
        320.0  1.50000
        325.0  1.55000
        330.0  1.60000
        335.0  1.65000
        340.0  1.70000
        345.0  1.75000
        350.0  1.80000
        355.0  1.85000
        360.0  1.90000
        365.0  1.95000
        370.0  2.00000
        375.0  2.05000
        380.0  2.10000
        385.0  2.15000
        390.0  2.20000
        395.0  2.25000
        400.0  2.30000
        405.0  2.35000
        410.0  2.40000
    end values
  end function slide

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon

  # Fully integrated at GPa contact pressures (verification/hertz/README.md: penalty point forces
  # excite the hourglass modes of one-point elements).
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8

  begin finite element model asperity
    begin generated asperity
      radius = 27 nm
      tip width = 24 nm
      tip height = 13 nm
      substrate width = 48 nm
      substrate depth = 24 nm
      element size = 0.5 nm
      fine half width = 9.5 nm   # the contact (a ~ 4.5 nm) slides 2.4 nm in +x and stays inside
      fine depth = 3.0 nm
      grading ratio = 1.3
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

  begin presto procedure indent_hold_slide
    begin time control
      termination time = 410.0 ps
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
        components = y
      end fixed displacement
      begin prescribed displacement
        node set = tip_top
        component = z
        function = push
        scale factor = -1
      end prescribed displacement
      begin prescribed displacement
        node set = tip_top
        component = x
        function = slide
      end prescribed displacement
      begin contact definition tip_on_flat
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        contact axis = 0 0 0 0 0 1 nm
        begin interaction sphere_flat
          surfaces = tip flat
          model = junction
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm        # 20 z0: the law keeps 99 % of W (docs/theory.md 6.3)
          junction strength = 195 MPa
          junction reference speed = 0.1 m/s   # no stability floor (backward Euler): tanh(V/v_ref) = 1 in sliding
          junction gap tolerance = 0 nm
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 2 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex
      end history output hist
      begin results output fields
        time increment = 50 ps
        nodal variables = displacement contact_traction contact_status
      end results output fields
    end presto region main
  end presto procedure indent_hold_slide
end sierra sphere_sliding_fine
