# expect: 18: 'tip width': the column corners
# Three violated limits of the asperity generator (R = 15 nm): tip width, tip height and fine half width,
# reported at once, one line each with the nearest valid value (mesh/README.md "Asperity generator limits");
# tests/bad_decks/CMakeLists.txt counts the lines (bad_deck_cli_asperity_three_limits_count).
begin sierra asperity_three_limits
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end
  end
  begin solid section hex8
  end
  begin finite element model asperity
    begin generated asperity
      radius = 15 nm
      tip width = 30 nm
      tip height = 3 nm
      substrate width = 60 nm
      substrate depth = 30 nm
      element size = 1 nm
      fine half width = 12 nm
    end
    begin parameters for block tip
      material = silicon
      section = hex8
    end
    begin parameters for block substrate
      material = silicon
      section = hex8
    end
  end
  begin presto procedure p
    begin time control
      termination time = 1 ps
    end
    begin presto region r
      use finite element model = asperity
    end
  end
end
