# rough_flats.i -- grid-scale rough-surface (GW) contact on flats (issue 10 acceptance): a block whose
# bottom carries the summit population of AFM sample di-3 is pressed onto a fixed flat, then slid.
#
# Run:    build/bin/tribex run verification/rough_flats/rough_flats.i -o rough_flats_output
# Check:  /usr/bin/python3 verification/rough_flats/compare.py rough_flats_output/history.csv
#
#          upper_zmax: lowered 140 nm (0-100 ns), held, then slid +x at 5 m/s (150-200 ns)
#        +--------+     block `upper`: 2 x 2 x 1 um polysilicon, free in x, y (uniaxial stress:
#        +--------+     uniform gap); upper_zmin (slave) carries the summits
#   +--------------+    block `lower`: 3 x 3 x 1 um, every node fixed (the rigid flat)
#
# Gap: the blocks start touching (node-to-face gap g = 0) with `mean plane offset` = 200 nm, so the
# mean-plane separation d = g + 200 nm starts at 5.7 sigma_s (no asperity load) and is closed to
# d = 60 nm = 1.7 sigma_s (about 110 MPa) by the press; d is read back as 200 nm + the mean z displacement of
# upper_zmin (the lower block does not move). Summits from `tribex surface stats
# inputs/data/afm/di-3.di` (isotropic): eta = 26.14 /um^2, R_s = 192.9 nm, sigma_s = 35.01 nm;
# E* = E / (2 (1 - nu^2)) = 84.1 GPa for polysilicon on polysilicon; W = 0.05 J/m^2; tau* = 100 MPa.
# Quasi-static: the press lasts 100 ns, about 800 transits of the 1 um block (c_d = 8 km/s), with
# mass damping; the compare script checks kinetic energy < 2 % of internal energy in the windows used.
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
