# shear.i -- J2 plasticity with linear isotropic hardening in simple shear (docs/theory.md 3.3;
# verification/plasticity/README.md): a 10 nm cube of 2 x 2 x 1 fully integrated hex8 (two pairs of
# elements, one per SSE lane), every node on the bottom (held) or the top face, the top sheared in x
# to 5 times the yield shear strain in 200 ps and brought back by 2 yield strains by 300 ps. The
# strain is homogeneous: H_xz = gamma = u_x / 10 nm.
#
# Run:    build/bin/tribex run verification/plasticity/shear.i -o shear_output
# Check:  /usr/bin/python3 verification/plasticity/compare.py shear_output --path shear
#
# (The table runs on to 310 ps so that the drive keeps its speed through the last row.)
# Expected: tau = mu gamma up to tau_y = Y/sqrt(3), then tau_y + G_t (gamma - gamma_y),
# G_t = mu (K/3)/(mu + K/3); unloading with slope mu. Y = 4 GPa, K = 20 GPa.
begin sierra plasticity_shear
  begin function shear
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0    0
      200  1.76433
      300  1.05860
      310  0.98803
    end values
  end function shear
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
    formulation = fully_integrated
  end solid section hex8
  begin finite element model cube
    begin generated box cube
      origin = 0 0 0 nm
      size = 10 10 10 nm
      intervals = 2 2 1
    end generated box cube
    begin parameters for block cube
      material = hardened_silicon
      model = j2_plasticity
      section = hex8
    end parameters for block cube
  end finite element model cube
  begin presto procedure shear
    begin time control
      termination time = 300 ps
    end time control
    begin presto region main
      use finite element model cube
      quasi static = on
      mass damping coefficient = 5e10 1/s
      begin fixed displacement
        node set = cube_zmin
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = cube_zmax
        components = y z
      end fixed displacement
      begin prescribed displacement
        node set = cube_zmax
        component = x
        function = shear
      end prescribed displacement
      begin history output hist
        time increment = 2 ps
        reaction force = cube_zmax
        mean displacement = cube_zmax
      end history output hist
    end presto region main
  end presto procedure shear
end sierra plasticity_shear
