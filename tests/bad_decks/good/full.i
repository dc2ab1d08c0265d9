# Every block and key of the deck language (tests/inputs/parser_test.cpp checks the values).
# A silicon tip pressed on a substrate: nm/ps units, functions with unit keys, all BCs.
begin sierra tip_on_flat
  begin function ramp
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0    0
      10   -2.5
      20   -2.5
    end values
  end function ramp

  begin function load
    type is piecewise linear
    begin values
      0 0
      1e-9 1e6
    end
  end function load

  Begin Property Specification For Material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
    begin parameters for model neohookean
      bulk modulus = 100 GPa
      shear modulus = 60 GPa
    end parameters for model neo_hookean
  end property specification for material silicon

  begin solid section hex8
    formulation = fully_integrated
    hourglass stiffness = 0.1
    hourglass viscosity = 0.01
    linear bulk viscosity = 0.05
    quadratic bulk viscosity = 1.0
  end solid section hex8

  begin finite element model tip_model
    database type = generated
    begin generated box substrate
      origin = 0 0 -20 nm
      size = 100 100 20 nm
      intervals = 10 10 4
      grade toward = zmax
      grading ratio = 1.1
    end generated box substrate
    begin surface layer block substrate_skin
      from block = substrate
      surface = substrate_zmax
      layers = 2
    end surface layer block substrate_skin
    begin parameters for block substrate
      material = silicon
      model = neo_hookean
      section = hex8
    end parameters for block substrate
    begin parameters for block substrate_skin
      material = silicon
      section = hex8
    end parameters for block substrate_skin
  end finite element model tip_model

  begin presto procedure explicit
    begin time control
      start time = 0
      termination time = 10 ns
      time step scale factor = 0.8
      maximum time step = 1 ps
    end time control
    begin presto region tip
      use finite element model tip_model
      begin fixed displacement
        node set = substrate_zmin
        components = x y z
      end fixed displacement
      begin prescribed displacement
        node set = substrate_zmax
        component = z
        function = ramp
        scale factor = 2
      end prescribed displacement
      begin prescribed velocity
        node set = substrate_xmax
        component = x
        function = ramp
        scale factor = 1 1/s
      end prescribed velocity
      begin initial velocity
        block = substrate
        velocity = 0 0 -1 m/s
      end initial velocity
      begin pressure
        side set = substrate_xmin
        function = load
        scale factor = 2 Pa
      end pressure
      begin silent boundary
        side set = substrate_ymin
        normal coefficient = 0.5
        tangential coefficient = 0.25
      end silent boundary
      mass damping coefficient = 1e8 1/s
      energy error limit = 0.1
      begin results output out
        time increment = 100 ps
        nodal variables = displacement velocity force acceleration
        element variables = stress
        format = both
      end results output out
      begin history output hist
        step increment = 10
        reaction force = substrate_zmin, substrate_zmax
        mean displacement = substrate_zmax
      end history output hist
      begin restart output
        step increment = 1000
        wall time increment = 1800 s
        ring size = 3
      end restart output
      begin rigid body lid
        node set = substrate_ymax
        reference point = 0 1 0 nm
        rotation = fixed
      end rigid body lid
      begin prescribed force
        rigid body = lid
        component = y
        function = load
        scale factor = 1 N
      end prescribed force
      begin rigid body cap
        block = substrate_skin
        rotation = free
        rotation axes = z
      end rigid body cap
      begin prescribed rotation
        rigid body = cap
        component = x
        function = load
        scale factor = 1e-6
        angle unit = deg
      end prescribed rotation
      begin prescribed angular velocity
        rigid body = cap
        component = y
        function = load
        scale factor = 2 1/s
      end prescribed angular velocity
      begin prescribed displacement
        rigid body = cap
        component = x
        function = ramp
      end prescribed displacement
    end presto region tip
  end presto procedure explicit
end sierra tip_on_flat
