# expect: 85: 'force direction = axis' needs 'contact axis
begin sierra force_direction_flats
  begin function squeeze
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0    0
      20   0.05
      150  0.05
    end values
  end function squeeze
  begin function slide
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0    0
      30   0
      60   0.3
      120  -0.3
      150  -0.3
    end values
  end function slide
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin solid section hex8
  end solid section hex8
  begin finite element model blocks
    begin generated box lower
      origin = -5 0 0 nm
      size = 20 10 5 nm
      intervals = 8 4 2
    end generated box lower
    begin generated box upper
      origin = 0 0 5 nm
      size = 10 10 5 nm
      intervals = 3 3 2
    end generated box upper
    begin parameters for block lower
      material = silicon
      section = hex8
    end parameters for block lower
    begin parameters for block upper
      material = silicon
      section = hex8
    end parameters for block upper
  end finite element model blocks
  begin presto procedure press_and_slide
    begin time control
      termination time = 150 ps
    end time control
    begin presto region main
      use finite element model blocks
      mass damping coefficient = 2e11 1/s
      begin fixed displacement
        node set = lower_zmin
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = upper_zmax
        components = y
      end fixed displacement
      begin prescribed displacement
        node set = upper_zmax
        component = z
        function = squeeze
        scale factor = -1
      end prescribed displacement
      begin prescribed displacement
        node set = upper_zmax
        component = x
        function = slide
      end prescribed displacement
      begin contact definition interface
        contact surface upper_face contains upper_zmin
        contact surface lower_face contains lower_zmax
        begin interaction press
          surfaces = upper_face lower_face
          force direction = axis
        end interaction press
      end contact definition interface
      begin history output hist
        step increment = 10
        reaction force = upper_zmax lower_zmin
      end history output hist
    end presto region main
  end presto procedure press_and_slide
end sierra force_direction_flats
