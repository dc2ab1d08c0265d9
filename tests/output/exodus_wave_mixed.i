# exodus_wave_mixed.i -- exodus_wave.i with mixed blocks: the 3 element layers of `bar` under its
# loaded end (bar_zmax) split off as block `bar_end`, fully integrated (`begin surface layer block`,
# mesh/README.md). The checks of exodus_wave.i hold with the extra block, and a run on the unsplit mesh
# read back from results.exo / .msh (split at set-up) repeats this run's history.csv byte for byte
# (CTest output_exodus_mixed_*).
#
# exodus_wave.i -- tests/parallel/mpi_wave.i (the coarse wave bar, 2 x 2 x 30 hex8) plus a second
# block `cap` beside it, sheared by its own piston, with every nodal and element field and
# `format = both`: results.h5 + results.xdmf and results.exo from the same run. tests/output/
# check_exodus.py compares the two files field by field (1e-12), the Exodus globals with
# history.csv, the block and set names, a restarted run's results.exo with an uninterrupted one's,
# and a run on this mesh read back from results.exo with the generated one (CTest output_exodus_*).
#
# Run:    build/bin/tribex run tests/output/exodus_wave_mixed.i -o exodus_wave_mixed_output
begin sierra exodus_wave_mixed
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
  begin solid section hex8_fi
    formulation = fully_integrated
  end solid section hex8_fi

  begin finite element model column
    begin generated box bar
      size = 4 4 60 nm
      intervals = 2 2 30
    end generated box bar
    begin generated box cap
      origin = 10 0 0 nm
      size = 6 4 20 nm
      intervals = 3 2 6
      grade toward = zmax
      grading ratio = 1.1
    end generated box cap
    begin surface layer block bar_end
      from block = bar
      surface = bar_zmax
      layers = 3
    end surface layer block bar_end
    begin parameters for block bar_end
      material = silicon
      section = hex8_fi
    end parameters for block bar_end
    begin parameters for block bar
      material = silicon
      model = elastic
      section = hex8
    end parameters for block bar
    begin parameters for block cap
      material = silicon
      model = elastic
      section = hex8
    end parameters for block cap
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
      begin fixed displacement
        node set = cap_zmin
        components = x y z
      end fixed displacement
      begin prescribed velocity
        node set = cap_zmax
        component = x
        function = piston
        scale factor = 2      # shears the cap
      end prescribed velocity
      begin history output waves
        step increment = 1
        reaction force = bar_zmin bar_zmax
        mean displacement = cap_zmax
      end history output waves
      begin results output fields
        time increment = 2 ps
        nodal variables = displacement velocity force acceleration
        element variables = stress equivalent_plastic_strain
        format = both
      end results output fields
      begin restart output
        step increment = 1000   # only when stopped early (--stop-at-step): the restart check
      end restart output
    end presto region column
  end presto procedure wave
end sierra exodus_wave_mixed
