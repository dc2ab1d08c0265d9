# expect: 19: block 'bx' is not in the mesh (did you mean 'box'?)
# The surface layer block splits a block the mesh does not have.
begin sierra surface_layers
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
    begin surface layer block skin
      from block = bx
      surface = box_zmax
      layers = 1
    end surface layer block skin
    begin parameters for block box
      material = steel
      section = hex8
    end parameters for block box
    begin parameters for block skin
      material = steel
      section = hex8
    end parameters for block skin
  end finite element model m
  begin presto procedure p
    begin time control
      termination time = 1 us
    end time control
    begin presto region r
      use finite element model m
      begin fixed displacement
        node set = box_zmin
        components = z
      end fixed displacement
    end presto region r
  end presto procedure p
end sierra surface_layers
