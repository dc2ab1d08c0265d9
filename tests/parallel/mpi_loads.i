# mpi_loads.i -- applied loads under a domain decomposition, for tests/parallel/: a silicon block
# (4 x 4 x 12 nm, 4 x 4 x 12 fully integrated hex8) fixed at its base, pushed down by a prescribed
# nodal force on its top (a 50 nN total shared by the top nodes) and sideways by a pressure on one
# side, with mass damping. METIS cuts the top and the loaded side between the ranks, so both loads
# have nodes shared by several ranks: every history column at 2 and 4 ranks must agree with one
# rank to 1e-10 relative (a load applied on every copy of a shared node, or on none, shows in the
# external work and the displacements at once).
#
# Run:    mpirun -np 2 build/bin/tribex run tests/parallel/mpi_loads.i -o mpi_loads_np2
begin sierra mpi_loads
  begin function ramp
    type = piecewise linear
    abscissa unit = ps
    begin values
      0.0   0.0
      5.0   1.0
      100.0 1.0
    end values
  end function ramp

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
      begin fixed displacement
        node set = block_zmin
        components = x y z
      end fixed displacement
      begin prescribed force
        node set = block_zmax
        component = z
        function = ramp
        scale factor = -50 nN
      end prescribed force
      begin pressure
        side set = block_xmin
        function = ramp
        scale factor = 1 GPa
      end pressure
      begin history output loads
        step increment = 5
        reaction force = block_zmin
        mean displacement = block_zmax
      end history output loads
      # restart files for the N -> M rank restart test (mpi_restart_loads_np1_to_np3): the applied loads'
      # nodal forces, partial sums on shared nodes, are formed again on the new ranks
      begin restart output
        step increment = 1000
      end restart output
    end presto region column
  end presto procedure loads
end sierra mpi_loads
