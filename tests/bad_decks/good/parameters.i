# Deck parameters (inputs/README.md "Parameters"): definitions with units and arithmetic, uses in
# values with one shared trailing unit, in a list, and inside a name.
{L = 1 mm}                 # edge of the cube
{n = 2}                    # intervals per edge
{E = 200 GPa}
{c = (E / (7850 kg/m^3))^(1/2) / 1 m/s}   # dimensionless wave speed in m/s (5047.5...)
begin sierra parameters
  begin property specification for material steel
    density = 7850
    begin parameters for model elastic
      youngs modulus = {E * 1.05}
      poissons ratio = {0.6 / 2}
    end
  end
  begin solid section sec
  end
  begin finite element model m
    begin generated box cube
      size = {L} {L} {2 * L}
      intervals = {n} {n} {2*n}
    end
    begin parameters for block cube
      material = steel
      section = sec
    end
  end
  begin presto procedure p
    begin time control
      termination time = {4 * L / (c * 1 m/s)}
    end
    begin presto region r
      use finite element model = m
    end
  end
end
