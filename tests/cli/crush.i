# A block whose top is driven 3 times its height into it in 1 ps: an element inverts and the run
# must stop with exit code 3, naming the element, with valid output files left behind.
begin sierra crush
  begin function smash
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0 0
      1 30
    end values
  end function smash
  begin property specification for material steel
    density = 7800 kg/m^3
    begin parameters for model neo_hookean
      youngs modulus = 200 GPa
      poissons ratio = 0.3
    end parameters for model neo_hookean
  end property specification for material steel
  begin solid section hex8
  end solid section hex8
  begin finite element model m
    begin generated box box
      size = 10 10 10 nm
      intervals = 2 2 2
    end generated box box
    begin parameters for block box
      material = steel
      model = neo_hookean
      section = hex8
    end parameters for block box
  end finite element model m
  begin presto procedure p
    begin time control
      termination time = 2 ps
    end time control
    begin presto region r
      use finite element model m
      begin fixed displacement
        node set = box_zmin
        components = x y z
      end fixed displacement
      begin prescribed displacement
        node set = box_zmax
        component = z
        function = smash
        scale factor = -1
      end prescribed displacement
      begin history output h
        step increment = 1
      end history output h
      begin results output f
        step increment = 5
        nodal variables = displacement
        element variables = stress
      end results output f
    end presto region r
  end presto procedure p
end sierra crush
