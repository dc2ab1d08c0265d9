# expect: 44: node set 'no_such_set'
# A history output names a node set the mesh does not have: check must say so (it passed, and run ended in map::at; issue 29, item 1).
begin sierra history_set
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
    begin generated box lid
      origin = 0 0 1 mm
      size = 1 1 1 mm
      intervals = 2 2 2
    end generated box lid
    begin parameters for block box
      material = steel
      section = hex8
    end parameters for block box
    begin parameters for block lid
      material = steel
      section = hex8
    end parameters for block lid
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
      begin history output h
        step increment = 1
        reaction force = box_zmin no_such_set
      end history output h
    end presto region r
  end presto procedure p
end sierra history_set
