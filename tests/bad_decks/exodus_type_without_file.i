# expect: 13: 'database type = exodus' needs 'database name = FILE.exo'
begin sierra exodus_type_without_file
  begin property specification for material steel
    density = 7850 kg/m^3
    begin parameters for model elastic
      youngs modulus = 200 GPa
      poissons ratio = 0.3
    end parameters for model elastic
  end property specification for material steel
  begin solid section hex8
  end solid section hex8
  begin finite element model body
    database type = exodus
    begin generated box b
      size = 1 1 1 nm
      intervals = 1 1 1
    end generated box b
    begin parameters for block b
      material = steel
      model = elastic
      section = hex8
    end parameters for block b
  end finite element model body
  begin presto procedure p
    begin time control
      termination time = 1 ps
    end time control
    begin presto region r
      use finite element model body
    end presto region r
  end presto procedure p
end sierra exodus_type_without_file
