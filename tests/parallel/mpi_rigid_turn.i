# mpi_rigid_turn.i -- a turning rigid body under a domain decomposition, for tests/parallel/: the column of
# mpi_rigid_body.i (neo-Hookean here: objective under the cap's rotation), its top face a rigid body `cap`
# turned 2 degrees about z by a prescribed rotation (held about x and y), pushed down by a
# prescribed force (50 nN) and sideways by a prescribed displacement in x, with a pressure on one side.
# METIS cuts the top face between the ranks: the body's momentum and angular momentum are summed over the
# ranks each step and every copy of its nodes gets the same velocity. Every history column at 2 and 4
# ranks, the body's reaction, moment, rotation and angular velocity included, must agree with one rank
# to 1e-10 relative (docs/theory.md 1.6).
#
# Run:    mpirun -np 2 build/bin/tribex run tests/parallel/mpi_rigid_turn.i -o mpi_rigid_turn_np2
begin sierra mpi_rigid_turn
  begin function ramp
    type = piecewise linear
    abscissa unit = ps
    begin values
      0.0   0.0
      5.0   1.0
      100.0 1.0
    end values
  end function ramp
  begin function shift
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0.0   0.0
      10.0  0.02
    end values
  end function shift

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model neo_hookean
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model neo_hookean
  end property specification for material silicon

  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8

  begin finite element model column
    begin generated box block
      size = 4 4 12 nm
      intervals = 4 4 12
    end generated box block
    begin parameters for block block
      material = silicon
      model = neo_hookean
      section = hex8
    end parameters for block block
  end finite element model column

  begin presto procedure loads
    begin time control
      termination time = 10 ps
    end time control
    begin presto region column
      use finite element model column
      mass damping coefficient = 1e11 1/s
      begin rigid body cap
        node set = block_zmax
        reference point = 1 2 12 nm
      end rigid body cap
      begin fixed displacement
        node set = block_zmin
        components = x y z
      end fixed displacement
      begin prescribed rotation
        rigid body = cap
        component = z
        function = ramp
        scale factor = 2
        angle unit = deg
      end prescribed rotation
      begin prescribed force
        rigid body = cap
        component = z
        function = ramp
        scale factor = -50 nN
      end prescribed force
      begin prescribed displacement
        rigid body = cap
        component = x
        function = shift
      end prescribed displacement
      begin pressure
        side set = block_ymin
        function = ramp
        scale factor = 1 GPa
      end pressure
      begin history output loads
        step increment = 5
        reaction force = block_zmin
        mean displacement = block_zmax
      end history output loads
    end presto region column
  end presto procedure loads
end sierra mpi_rigid_turn
