# expect: 30: largest factor
# begin mass scaling: a negative largest factor.
begin sierra mass_scaling
  begin property specification for material steel
    density = 7800 kg/m^3
    begin parameters for model elastic
      youngs modulus = 200 GPa
      poissons ratio = 0.3
    end parameters for model elastic
  end property specification for material steel
  begin solid section hex8
  end solid section hex8
  begin finite element model m
    begin generated box box
      size = 1 1 1 mm
      intervals = 2 2 2
    end generated box box
    begin parameters for block box
      material = steel
      section = hex8
    end parameters for block box
  end finite element model m
  begin presto procedure p
    begin time control
      termination time = 1 us
    end time control
    begin presto region r
      use finite element model m
      begin mass scaling
        largest factor = -2
      end mass scaling
    end presto region r
  end presto procedure p
end sierra mass_scaling
