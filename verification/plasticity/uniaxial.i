# uniaxial.i -- J2 plasticity with linear isotropic hardening under uniaxial stress (docs/theory.md
# 3.3; verification/plasticity/README.md): a 10 nm cube of 2 x 2 x 2 mean-quadrature hex8 on
# symmetry planes (x = 0, y = 0, z = 0 held normal), its x = 10 nm face pulled to 4 times the yield
# strain in 200 ps, then brought back by 1.5 yield strains (elastic unloading) by 300 ps.
#
# Run:    build/bin/tribex run verification/plasticity/uniaxial.i -o uniaxial_output
# Check:  /usr/bin/python3 verification/plasticity/compare.py uniaxial_output --path uniaxial
#
# (The table runs on to 310 ps so that the drive keeps its speed through the last row.)
# Expected: sigma = E eps up to Y, then Y + E_t (eps - Y/E), E_t = E K/(E + K); on unloading the slope
# is E again. Plastic dissipation = V (Y eps_p + K eps_p^2 / 2) with eps_p the plastic strain at the top.
# Y = 4 GPa (about a third of silicon's nanoindentation hardness), K = 20 GPa.
begin sierra plasticity_uniaxial
  begin function pull
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0    0
      200  0.99379
      300  0.62112
      310  0.58385
    end values
  end function pull
  begin property specification for material hardened_silicon
    density = 2330 kg/m^3
    begin parameters for model j2_plasticity
      youngs modulus = 161 GPa
      poissons ratio = 0.23
      yield stress = 4 GPa
      hardening modulus = 20 GPa
    end parameters for model j2_plasticity
  end property specification for material hardened_silicon
  begin solid section hex8
    formulation = mean_quadrature
  end solid section hex8
  begin finite element model cube
    begin generated box cube
      origin = 0 0 0 nm
      size = 10 10 10 nm
      intervals = 2 2 2
    end generated box cube
    begin parameters for block cube
      material = hardened_silicon
      model = j2_plasticity
      section = hex8
    end parameters for block cube
  end finite element model cube
  begin presto procedure pull
    begin time control
      termination time = 300 ps
    end time control
    begin presto region main
      use finite element model cube
      quasi static = on
      # Damps the ringing of the start (strain v/c = 5.7e-4) within about 40 ps; its force on the
      # quasi-static stretch is under 0.1 % of the yield force.
      mass damping coefficient = 5e10 1/s
      begin fixed displacement
        node set = cube_xmin
        components = x
      end fixed displacement
      begin fixed displacement
        node set = cube_ymin
        components = y
      end fixed displacement
      begin fixed displacement
        node set = cube_zmin
        components = z
      end fixed displacement
      begin prescribed displacement
        node set = cube_xmax
        component = x
        function = pull
      end prescribed displacement
      begin history output hist
        time increment = 2 ps
        reaction force = cube_xmax
        mean displacement = cube_xmax
      end history output hist
    end presto region main
  end presto procedure pull
end sierra plasticity_uniaxial
