# wave_v1.i -- tests/parallel/mpi_wave.i shortened to 4 x 4 x 40 nm (2 x 2 x 20 hex8), the deck of the
# version-1 restart file beside it (README.md): restart_v1_np1.h5 was written by
# tribex at commit 72c57ee5 (the last writer of format version 1, the ranks in turn) on 1 rank,
# stopped after step 50. Kept so that a restart file from before format version 2 still resumes.
#
# Run:    build/bin/tribex run tests/parallel/restart_v1/wave_v1.i -o OUT
begin sierra wave_v1
  begin function piston
    type = piecewise linear
    abscissa unit = ps
    begin values
      0.0   0.0
      1.0   1.0
      100.0 1.0
    end values
  end function piston

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model elastic
  end property specification for material silicon

  begin solid section hex8
    formulation = mean_quadrature
  end solid section hex8

  begin finite element model column
    begin generated box bar
      size = 4 4 40 nm
      intervals = 2 2 20
    end generated box bar
    begin parameters for block bar
      material = silicon
      model = elastic
      section = hex8
    end parameters for block bar
  end finite element model column

  begin presto procedure wave
    begin time control
      termination time = 20 ps
      time step scale factor = 0.9
    end time control
    begin presto region column
      use finite element model column
      begin fixed displacement
        node set = bar_xmin
        components = x
      end fixed displacement
      begin fixed displacement
        node set = bar_xmax
        components = x
      end fixed displacement
      begin fixed displacement
        node set = bar_ymin
        components = y
      end fixed displacement
      begin fixed displacement
        node set = bar_ymax
        components = y
      end fixed displacement
      begin fixed displacement
        node set = bar_zmin
        components = z
      end fixed displacement
      begin prescribed velocity
        node set = bar_zmax
        component = z
        function = piston
        scale factor = -1      # pushes down (compression)
      end prescribed velocity
      begin history output waves
        step increment = 1
        reaction force = bar_zmin bar_zmax
      end history output waves
      begin results output fields
        time increment = 1 ps
        nodal variables = displacement velocity
        element variables = stress
      end results output fields
      begin restart output
        step increment = 1000
      end restart output
    end presto region column
  end presto procedure wave
end sierra wave_v1
