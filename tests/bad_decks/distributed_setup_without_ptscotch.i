# expect: 42: needs 'method = ptscotch'
# set-up = distributed with the default method (metis)
begin sierra bad
  begin function ramp
    type = piecewise linear
    begin values
      0 0
      1e-9 1e-9
    end values
  end function ramp
  begin property specification for material steel
    density = 7850 kg/m^3
    begin parameters for model elastic
      youngs modulus = 200 GPa
      poissons ratio = 0.3
    end parameters for model elastic
  end property specification for material steel
  begin solid section sec
  end solid section sec
  begin finite element model m
    begin generated box cube
      size = 10 10 10 nm
      intervals = 2 2 2
    end generated box cube
    begin parameters for block cube
      material = steel
      section = sec
    end parameters for block cube
  end finite element model m
  begin presto procedure p
    begin time control
      termination time = 1 ns
    end time control
    begin presto region r
      use finite element model m
      begin prescribed displacement
        node set = cube_zmax
        component = z
        function = ramp
      end prescribed displacement
      begin decomposition
        set-up = distributed
      end decomposition
    end presto region r
  end presto procedure p
end sierra bad
