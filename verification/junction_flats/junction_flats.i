# junction_flats.i -- junction model on flats (docs/theory.md 7.3 handle; issue 4): a block pressed on a
# wider block, then slid forth and back at constant speed while the press is held.
#
# Run:    build/bin/tribex run verification/junction_flats/junction_flats.i -o junction_flats_output
# Check:  /usr/bin/python3 verification/junction_flats/compare.py junction_flats_output/history.csv
#
#            upper_zmax: pressed down 0.05 nm (0-20 ps, 1 % strain), held (displacement hold, not load control);
#        +-----------+     slid in x: +0.3 nm over 30-60 ps (+10 m/s), -0.6 nm over 60-120 ps (-10 m/s)
#        +-----------+     block `upper`: 10 x 10 x 5 nm; upper_zmin (slave) on lower_zmax (master)
#   +---------------------+  block `lower`: 20 x 10 x 5 nm, wider in x so the slid face stays on it
#            lower_zmin: fixed
# Expected in steady sliding (40-60 ps, 80-120 ps): friction = tau* A_real tanh(V/v_ref) = tau* x
# 100 nm^2 = 1 nN (default v_ref = 0.1 m/s, V/v_ref = 100: the shear is backward Euler per pair, with
# no stability floor on v_ref; an explicit update would need v_ref > 1.07 m/s here), opposing the sliding: the base reaction lower_zmin x flips sign with V. (The top
# reaction also carries the mass-damping force of the moving block.) Slow speeds: an abrupt change of
# the top velocity by dV sends a shear wave of strain dV/c_s, which at 100 m/s rivals the 1 % press.
begin sierra junction_flats
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
        begin interaction junction
          surfaces = upper_face lower_face
          model = junction
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.2 nm
          junction strength = 10 MPa
        end interaction junction
      end contact definition interface
      begin history output hist
        step increment = 10
        reaction force = upper_zmax lower_zmin
      end history output hist
    end presto region main
  end presto procedure press_and_slide
end sierra junction_flats
