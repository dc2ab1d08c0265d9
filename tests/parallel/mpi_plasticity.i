# mpi_plasticity.i -- J2 plasticity state across ranks and restarts (tests/parallel/README.md): two
# cubes side by side, one of mean-quadrature and one of fully integrated hex8 (the two layouts of
# the material state), each pulled in x past yield and partly back, sheared a little in y so that
# the flow is not uniform. Checked: 1 vs 2 and 4 ranks agree; stopped + resumed = uninterrupted.
begin sierra mpi_plasticity
  begin function pull
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0    0
      60   0.8
      90   0.5
    end values
  end function pull
  begin function slant
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0    0
      90   0.3
    end values
  end function slant
  begin property specification for material hardened_silicon
    density = 2330 kg/m^3
    begin parameters for model j2_plasticity
      youngs modulus = 161 GPa
      poissons ratio = 0.23
      yield stress = 4 GPa
      hardening modulus = 20 GPa
    end parameters for model j2_plasticity
  end property specification for material hardened_silicon
  begin solid section one_point
    formulation = mean_quadrature
  end solid section one_point
  begin solid section eight_point
    formulation = fully_integrated
  end solid section eight_point
  begin finite element model cubes
    begin generated box mq
      origin = 0 0 0 nm
      size = 10 10 10 nm
      intervals = 4 4 4
    end generated box mq
    begin generated box fi
      origin = 0 20 0 nm
      size = 10 10 10 nm
      intervals = 3 3 3
    end generated box fi
    begin parameters for block mq
      material = hardened_silicon
      model = j2_plasticity
      section = one_point
    end parameters for block mq
    begin parameters for block fi
      material = hardened_silicon
      model = j2_plasticity
      section = eight_point
    end parameters for block fi
  end finite element model cubes
  begin presto procedure pull
    begin time control
      termination time = 90 ps
    end time control
    begin presto region main
      use finite element model cubes
      mass damping coefficient = 5e10 1/s
      begin fixed displacement
        node set = mq_xmin
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = fi_xmin
        components = x y z
      end fixed displacement
      begin prescribed displacement
        node set = mq_xmax
        component = x
        function = pull
      end prescribed displacement
      begin prescribed displacement
        node set = fi_xmax
        component = x
        function = pull
      end prescribed displacement
      begin prescribed displacement
        node set = mq_xmax
        component = y
        function = slant
      end prescribed displacement
      begin prescribed displacement
        node set = fi_xmax
        component = y
        function = slant
      end prescribed displacement
      begin history output hist
        step increment = 5
        reaction force = mq_xmax fi_xmax
      end history output hist
      begin results output fields
        time increment = 15 ps
        nodal variables = displacement
        element variables = stress equivalent_plastic_strain
      end results output fields
      begin restart output
        step increment = 1000   # written only when a run stops early
      end restart output
    end presto region main
  end presto procedure pull
end sierra mpi_plasticity
