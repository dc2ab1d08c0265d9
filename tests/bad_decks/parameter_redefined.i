# expect: 5: parameter 'E' is already defined at
# A parameter defined twice.
{E = 200 GPa}
begin sierra parameter_redefined
{E = 210 GPa}
  begin property specification for material steel
    density = 7850
    begin parameters for model elastic
      youngs modulus = {E}
      poissons ratio = 0.3
    end
  end
  begin solid section sec
  end
  begin finite element model m
    begin generated box cube
      size = 1 1 1 mm
      intervals = 2 2 2
    end
    begin parameters for block cube
      material = steel
      section = sec
    end
  end
  begin presto procedure p
    begin time control
      termination time = 1 us
    end
    begin presto region r
      use finite element model = m
    end
  end
end
