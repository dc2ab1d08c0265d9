# expect: 96: 'junction strength' applies to 'model = junction' or 'model = rough surface', not 'model = coulomb'
# block_pull.i -- Coulomb friction (issue 23): a block pressed on a rigid flat, then pulled along it.
#
# Run:    build/bin/tribex run verification/coulomb/block_pull.i -o coulomb_output
# Check:  /usr/bin/python3 verification/coulomb/compare.py coulomb_output/history.csv
#
#        +-----+        block `upper`: one 100 nm silicon element, free; its four bottom nodes
#        |     |        (upper_zmin, the slave face) carry the loads: N = 1 uN down (ramped 0-1 ns,
#   -->  +-----+        then held) and T(t) = 0.6 uN (t - 2 ns) / 4 ns along +x from 2 ns
#   +---------------+   block `lower`: 500 x 500 x 100 nm, every node fixed (the rigid flat)
#
# Loading the contact nodes themselves gives every node the same T/N (equal shares, no moment), so
# the whole face sticks while T < mu_s N and slides at once when T reaches mu_s N = 0.5 uN
# (t = 5.333 ns); it then slides with the friction mu_k N = 0.4 uN while T - mu_k N accelerates the
# block. The history is written every step so that compare.py can integrate the friction power and
# mu_k N du exactly as the solver steps.
begin sierra coulomb_block_pull
  begin function press
    type = piecewise linear
    abscissa unit = ns
    begin values
      0  0
      1  1
      7  1
    end values
  end function press
  begin function pull
    type = piecewise linear
    abscissa unit = ns
    begin values
      0  0
      2  0
      6  0.6
      7  0.75
    end values
  end function pull
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model elastic
  end property specification for material silicon
  begin solid section hex8
  end solid section hex8
  begin finite element model blocks
    begin generated box lower
      origin = -200 -200 -100 nm
      size = 500 500 100 nm
      intervals = 5 5 1
    end generated box lower
    begin generated box upper
      origin = 0 0 0 nm
      size = 100 100 100 nm
      intervals = 1 1 1
    end generated box upper
    begin parameters for block lower
      material = silicon
      section = hex8
    end parameters for block lower
    begin parameters for block upper
      material = silicon
      section = hex8
    end parameters for block upper
  end finite element model blocks
  begin presto procedure press_and_pull
    begin time control
      termination time = 6 ns
    end time control
    begin presto region main
      use finite element model blocks
      begin fixed displacement
        node set = lower_all
        components = x y z
      end fixed displacement
      begin prescribed force
        node set = upper_zmin
        component = z
        function = press
        scale factor = -1e-6 N
      end prescribed force
      begin prescribed force
        node set = upper_zmin
        component = x
        function = pull
        scale factor = 1e-6 N
      end prescribed force
      begin contact definition interface
        contact surface block_face contains upper_zmin
        contact surface flat_face contains lower_zmax
        begin interaction friction
          surfaces = block_face flat_face
          model = coulomb
          static friction coefficient = 0.5
          kinetic friction coefficient = 0.4
          junction strength = 100 MPa
        end interaction friction
      end contact definition interface
      begin history output hist
        step increment = 1
        mean displacement = upper_zmin
      end history output hist
      begin restart output
        step increment = 5000   # written only when a run stops early (tests/parallel: restart mid-slide)
      end restart output
    end presto region main
  end presto procedure press_and_pull
end sierra coulomb_block_pull
