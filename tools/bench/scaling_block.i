# scaling_block.i -- the block of the parallel scaling benchmark (tools/bench/parallel_scaling.py
# writes copies with other sizes): silicon, 1 nm hex8 (mean quadrature, elastic), bottom fixed,
# top pulled at 1 m/s; 5 ps = about 90 steps; history every 50 steps, no field output.
begin sierra scaling_block
  begin function pull
    type = piecewise linear
    abscissa unit = ps
    begin values
      0.0   1.0
      100.0 1.0
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
    formulation = mean_quadrature
  end solid section hex8
  begin finite element model block
    begin generated box block
      size = 60 60 60 nm
      intervals = 60 60 60
    end generated box block
    begin parameters for block block
      material = silicon
      model = elastic
      section = hex8
    end parameters for block block
  end finite element model block
  begin presto procedure pull
    begin time control
      termination time = 5 ps
    end time control
    begin presto region block
      use finite element model block
      begin fixed displacement
        node set = block_zmin
        components = x y z
      end fixed displacement
      begin prescribed velocity
        node set = block_zmax
        component = z
        function = pull
      end prescribed velocity
      begin history output h
        step increment = 50
      end history output h
    end presto region block
  end presto procedure pull
end sierra scaling_block
