# rough_flats_discrete.i -- the rough-surface model with a discrete summit population (issue 10
# acceptance: few asperities): the 10 summits found on a 0.8 x 0.8 um window of AFM sample di-3
# (di3_window_summits.csv, each summit with its own radius), on the rough_flats set-up.
#
# Run:    build/bin/tribex run verification/rough_flats/rough_flats_discrete.i -o rough_flats_discrete_output
# Check:  /usr/bin/python3 verification/rough_flats/compare_discrete.py rough_flats_discrete_output/history.csv
#
# Summit heights are measured from their mean (-6.6 to +7.1 nm); d = gap + 10 nm starts above the highest
# summit and the press (22 nm over 0-100 ns) brings every summit into contact (d = -6.9 nm, 0.83 GPa
# apparent; the block takes 5 nm of it). The load and real area per map area (6.104e-13 m^2) times
# the 4 um^2 face are compared with a direct sum over the summits (Hertz - 2 pi W R per contacting
# summit, pi R w) at the d read back from the run (mean z displacement of upper_zmin). No friction and
# no lateral constraint, so the upper block is in uniaxial stress; the remaining difference (0.5 %) is
# the block's non-uniform compression at 0.83 GPa (0.02 % with a 100x stiffer block).
begin sierra rough_flats_discrete
  begin function press
    type = piecewise linear
    abscissa unit = ns
    ordinate unit = nm
    begin values
      0    0
      100  22
      200  22
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
      termination time = 150 ns
    end time control
    begin presto region main
      use finite element model blocks
      mass damping coefficient = 2e8 1/s
      quasi static = on             # run guards: kinetic energy below 5 % of internal energy while loaded
      energy error warning = 0.015  # the damped approach peaks at 1.18 % (1.1 ns, energies 1e-16 J); 0.4 % once loaded
      begin fixed displacement
        node set = lower_all
        components = x y z
      end fixed displacement
      begin prescribed displacement
        node set = upper_zmax
        component = z
        function = press
        scale factor = -1
      end prescribed displacement
      begin contact definition interface
        contact surface upper_face contains upper_zmin
        contact surface lower_face contains lower_zmax
        begin interaction rough
          surfaces = upper_face lower_face
          model = rough surface
          summit file = di3_window_summits.csv
          summit map area = 6.10351562e-13 m^2
          composite modulus = 84.1 GPa
          work of adhesion = 0.05 J/m^2
          mean plane offset = 10 nm
        end interaction rough
      end contact definition interface
      begin history output hist
        step increment = 20
        mean displacement = upper_zmin
        reaction force = upper_zmax
      end history output hist
    end presto region main
  end presto procedure press_and_slide
end sierra rough_flats_discrete
