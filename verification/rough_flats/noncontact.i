# noncontact.i -- the rough-surface law with the attraction of the non-contacting area (issue 26,
# docs/theory.md 10.8): flats with the di-5 summits of the clamp example pressed together.
#
# Run:    build/bin/tribex run verification/rough_flats/noncontact.i -o noncontact_output
# Check:  /usr/bin/python3 verification/rough_flats/compare_noncontact.py noncontact_output/history.csv
#
# Block `upper` (2 x 2 x 1 um polysilicon, free in x, y) carries the summits of AFM sample di-5
# (`tribex surface stats inputs/data/afm/di-5.di`: eta = 3.796e16 /m^2, R_s = 14.71 nm,
# sigma_s = 1.536 nm) on its bottom face and is lowered 5 nm over 105 ns (the speed ramped up over
# the first 10 ns: a sudden start rings the block) onto the fixed block
# `lower`; W = 0.1 J/m^2, E* = 84.1 GPa. The blocks start touching with `mean plane offset` 10 nm
# (6.5 sigma_s: no asperity touches), so the mean-plane separation d = 10 nm + the mean z displacement
# of upper_zmin closes to 5 nm (3.3 sigma_s). The non-contact attraction (z0 = 0.2 nm, h_c = 200 z0)
# pulls from the start; the asperity contacts take over below about 4.5 sigma_s.
begin sierra rough_flats_noncontact
  begin function press
    type = piecewise linear
    abscissa unit = ns
    ordinate unit = nm
    begin values
      0    0
      2.5  0.015625
      5    0.0625
      7.5  0.140625
      10   0.25
      105  5
      120  5
    end values
  end function press
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
      termination time = 120 ns
    end time control
    begin presto region main
      use finite element model blocks
      mass damping coefficient = 2e8 1/s
      energy error warning = 0.02  # the driven start peaks at 1.3 % (0.44 ns, energies 1e-17 J; 0.95 % without the attraction); 0.05 % from 3 ns on
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
      begin fixed displacement
        node set = upper_zmax
        components = x
      end fixed displacement
      begin contact definition interface
        contact surface upper_face contains upper_zmin
        contact surface lower_face contains lower_zmax
        begin interaction rough
          surfaces = upper_face lower_face
          model = rough surface
          summit density = 3.796e16 1/m^2
          summit radius = 14.71 nm
          summit height deviation = 1.536 nm
          composite modulus = 84.1 GPa
          work of adhesion = 0.1 J/m^2
          mean plane offset = 10 nm
          noncontact equilibrium separation = 0.2 nm
        end interaction rough
      end contact definition interface
      begin history output hist
        step increment = 10
        mean displacement = upper_zmin
        reaction force = upper_zmax
      end history output hist
    end presto region main
  end presto procedure press_and_slide
end sierra rough_flats_noncontact
