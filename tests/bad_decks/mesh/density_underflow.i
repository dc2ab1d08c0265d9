# expect: 30: density 1e-300 kg/m^3 gives the elements of block 'bar'
# issue 54 item 16: a density whose element masses underflow to 0 was reported as a node of no element, with no deck line
# Run:    build/bin/tribex run inputs/examples/wave_bar.i -o wave_bar_output
# MPI:    mpirun -np 2 build/bin/tribex run inputs/examples/wave_bar.i -o wave_bar_np2
# Check:  /usr/bin/python3 verification/wave_bar/compare.py wave_bar_output/history.csv
#
#        bar_zmax  <- velocity ramped to 1 m/s in 1 ps (the "piston")
#        +--+
#        |  |  1 nm x 1 nm x 100 nm, 100 hex8 along z
#        |  |  lateral rollers: x fixed on bar_xmin/bar_xmax, y on bar_ymin/bar_ymax
#        |  |  (every node lies on those faces: uniaxial strain)
#        +--+
#        bar_zmin  fixed in z: the reaction there jumps to 2 rho c_d v0 A when the front arrives
#
# What it shows: wave speed c_d = sqrt((lambda + 2 mu)/rho) = 8854 m/s and the stress behind
# the front rho c_d v0 = 20.6 MPa (doubled at the fixed end), the mean-quadrature hex8 with bulk
# viscosity, prescribed velocity from a function, node-set reaction histories.
begin sierra wave_bar
  begin function piston
    type = piecewise linear
    abscissa unit = ps
    begin values
      0.0   0.0
      1.0   1.0
      100.0 1.0
    end values
  end function piston

  begin property specification for material silicon
    density = 1e-300 kg/m^3
    begin parameters for model elastic
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model elastic
  end property specification for material silicon

  begin solid section hex8
    formulation = mean_quadrature
  end solid section hex8

  begin finite element model column
    begin generated box bar
      size = 1 1 100 nm
      intervals = 1 1 100
    end generated box bar
    begin parameters for block bar
      material = silicon
      model = elastic
      section = hex8
    end parameters for block bar
  end finite element model column

  begin presto procedure wave
    begin time control
      termination time = 20 ps
      time step scale factor = 0.9
    end time control
    begin presto region column
      use finite element model column
      begin fixed displacement
        node set = bar_xmin
        components = x
      end fixed displacement
      begin fixed displacement
        node set = bar_xmax
        components = x
      end fixed displacement
      begin fixed displacement
        node set = bar_ymin
        components = y
      end fixed displacement
      begin fixed displacement
        node set = bar_ymax
        components = y
      end fixed displacement
      begin fixed displacement
        node set = bar_zmin
        components = z
      end fixed displacement
      begin prescribed velocity
        node set = bar_zmax
        component = z
        function = piston
        scale factor = -1      # pushes down (compression)
      end prescribed velocity
      begin history output waves
        step increment = 1
        reaction force = bar_zmin bar_zmax
      end history output waves
      begin results output fields
        time increment = 1 ps
        nodal variables = displacement velocity
        element variables = stress
      end results output fields
    end presto region column
  end presto procedure wave
end sierra wave_bar
