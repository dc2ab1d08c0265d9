# expect: 84: is taken from the summit file
begin sierra rough_flats
  begin function press
    type = piecewise linear
    abscissa unit = ns
    ordinate unit = nm
    begin values
      0    0
      100  140
      200  140
    end values
  end function press
  begin function slide
    type = piecewise linear
    abscissa unit = ns
    ordinate unit = nm
    begin values
      0    0
      150  0
      200  250
    end values
  end function slide
  begin property specification for material polysilicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model elastic
  end property specification for material polysilicon
  begin solid section hex8
  end solid section hex8
  begin finite element model blocks
    begin generated box lower
      origin = -0.5 -0.5 -1 um
      size = 3 3 1 um
      intervals = 5 5 1
    end generated box lower
    begin generated box upper
      origin = 0 0 0 um
      size = 2 2 1 um
      intervals = 4 4 2
    end generated box upper
    begin parameters for block lower
      material = polysilicon
      section = hex8
    end parameters for block lower
    begin parameters for block upper
      material = polysilicon
      section = hex8
    end parameters for block upper
  end finite element model blocks
  begin presto procedure press_and_slide
    begin time control
      termination time = 200 ns
    end time control
    begin presto region main
      use finite element model blocks
      mass damping coefficient = 2e8 1/s
      begin fixed displacement
        node set = lower_all
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = upper_zmax
        components = y
      end fixed displacement
      begin prescribed displacement
        node set = upper_zmax
        component = z
        function = press
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
        begin interaction rough
          surfaces = upper_face lower_face
          model = rough surface
          summit density = 26.14e12 1/m^2
          summit radius = 192.9 nm
          summit height deviation = 35.01 nm
          composite modulus = 84.1 GPa
          work of adhesion = 0.05 J/m^2
          junction strength = 100 MPa
          junction reference speed = 0.5 m/s
          summit file = summits.csv
          summit map area = 1 um^2
          mean plane offset = 200 nm
        end interaction rough
      end contact definition interface
      begin history output hist
        step increment = 20
        mean displacement = upper_zmin
        reaction force = upper_zmax
      end history output hist
    end presto region main
  end presto procedure press_and_slide
end sierra rough_flats
