# A slide longer than the tip column allows a fine region for (R = 15 nm, tip width 18 nm: fine half width
# below 9 nm): the substrate's fine strip 'fine x range = -4 20 nm' (issue 56 scope 5; mesh/README.md).
# tribex check must accept it (bad_deck_cli_good_asperity_fine_x_range).
begin sierra asperity_fine_x_range
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
      tip width = 18 nm
      tip height = 20 nm
      substrate width = 60 nm
      substrate depth = 30 nm
      element size = 1 nm
      fine x range = -4 20 nm
      fine half width = 4 nm
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
