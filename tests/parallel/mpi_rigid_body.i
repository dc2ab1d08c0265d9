# mpi_rigid_body.i -- a rigid body under a domain decomposition, for tests/parallel/: a silicon block
# (4 x 4 x 12 nm, fully integrated hex8) fixed at its base, its top face a rigid body `cap` pushed down
# by a prescribed force (50 nN) and sideways by a prescribed displacement in x, its y held through the
# body's node set, with a pressure on one side and mass damping. METIS cuts the top face between the
# ranks, so the body's nodes are shared: its momentum is summed over the ranks each step (owned nodes
# once) and every copy gets the same velocity. Every history column at 2 and 4 ranks, the body's
# reaction, displacement and moment included, must agree with one rank to 1e-10 relative.
#
# Run:    mpirun -np 2 build/bin/tribex run tests/parallel/mpi_rigid_body.i -o mpi_rigid_body_np2
begin sierra mpi_rigid_body
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
    begin parameters for model elastic
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model elastic
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
      begin fixed displacement
        node set = cap
        components = y
      end fixed displacement
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
end sierra mpi_rigid_body
