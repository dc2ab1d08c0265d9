# expect: 47: already driven about x
# one axis of a body driven twice (an angle and an angular velocity)
begin sierra bad
  begin function spin
    type is piecewise linear
    begin values
      0 0
      1e-6 1
    end
  end function spin
  begin property specification for material m
    density = 1000
    begin parameters for model elastic
      youngs modulus = 1e9
      poissons ratio = 0.3
    end parameters for model elastic
  end property specification for material m
  begin solid section s
  end solid section s
  begin finite element model fem
    begin generated box b
      origin = 0 0 0
      size = 1 1 1
      intervals = 2 2 2
    end generated box b
    begin parameters for block b
      material = m
      section = s
    end parameters for block b
  end finite element model fem
  begin presto procedure p
    begin time control
      termination time = 1e-6
    end time control
    begin presto region r
      use finite element model fem
      begin rigid body top
        node set = b_zmax
      end rigid body top
      begin prescribed rotation
        rigid body = top
        component = x
        function = spin
      end prescribed rotation
      begin prescribed angular velocity
        rigid body = top
        component = x
        function = spin
        scale factor = 1 1/s
      end prescribed angular velocity
    end presto region r
  end presto procedure p
end sierra bad
