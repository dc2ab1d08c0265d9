# expect: 3: cannot add a length (m) to a pressure (Pa)
# Bad expressions: dimensions that do not add (line 3), a dangling operator (line 4), an unclosed brace (line 10): all three reported.
{E = 200 GPa + 1 mm}
{L = (1 mm * }
begin sierra parameter_bad_expression
  begin property specification for material steel
    density = 7850
    begin parameters for model elastic
      youngs modulus = 200e9
      poissons ratio = {0.3
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
