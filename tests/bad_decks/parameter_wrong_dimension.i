# expect: 26: expected a time (s), got a length (m)
# A parameter with a unit used where another dimension is expected: the key's check names both.
{L = 1 mm}
begin sierra parameter_wrong_dimension
  begin property specification for material steel
    density = 7850
    begin parameters for model elastic
      youngs modulus = 200e9
      poissons ratio = 0.3
    end
  end
  begin solid section sec
  end
  begin finite element model m
    begin generated box cube
      size = {L} {L} {2*L}
      intervals = 2 2 2
    end
    begin parameters for block cube
      material = steel
      section = sec
    end
  end
  begin presto procedure p
    begin time control
      termination time = {L}
    end
    begin presto region r
      use finite element model = m
    end
  end
end
