# clamp.i -- nanotractor-style friction clamp (report Section 2.1; issue 10): a flat polysilicon foot
# (200 x 10 um, 2 um thick) pressed on a flat counterface whose roughness is that of AFM sample di-5,
# homogenized by the rough-surface (Greenwood-Williamson) interaction model, then pulled tangentially.
# One normal load per run; run_clamp.py runs several loads and fits F = mu (N + F_adh) (report Eq. 2.2).
#
# Run one load:  build/bin/tribex run inputs/examples/clamp_friction/clamp.i -o clamp_output
# All loads:     /usr/bin/python3 inputs/examples/clamp_friction/run_clamp.py --out clamp_friction_output
#
#   foot_zmax: pressure p = N / (200 x 10 um) ramped over 0-200 ns, then held
#   +------------------------------------------+  block `foot` 200 x 10 x 2 um; foot_xmin pulled in +x at
#   +------------------------------------------+  0.05 m/s from 600 ns (prescribed displacement: the foot's
#  +--------------------------------------------+ own axial stiffness, 16 kN/m, is the pull spring)
#  +--------------------------------------------+ block `counter`, every node fixed (the counterface)
#
# Rough surface: `tribex surface stats inputs/data/afm/di-5.di` (isotropic): summit density
# 3.796e16 /m^2, summit radius 14.71 nm, sigma_s 1.536 nm. E* = 84.1 GPa (polysilicon on polysilicon,
# E = 160 GPa, nu = 0.22), W = 0.1 J/m^2 (uncoated, hydrophilic), tau* = 1 GPa (junction shear strength).
# The mean-plane separation is d = gap + 9.2 nm (6 sigma_s: no load at the start, the foot touching the
# counterface in the mesh). Normal dynamics: the foot rides on the GW foundation (period 35 ns at
# 50 kPa, longer at lower loads); mass damping 5e7 1/s settles it before the pull (kinetic energy is
# checked by run_clamp.py). The friction force is the contact's (history friction_force), not the pull
# reaction, which also carries the mass-damping drag of the sliding foot.
begin sierra clamp_friction
  begin function ramp
    type = piecewise linear
    abscissa unit = ns
    begin values
      0    0
      200  1
      1200 1
    end values
  end function ramp
  begin function pull
    type = piecewise linear
    abscissa unit = ns
    ordinate unit = nm
    begin values
      0     0
      600   0
      1200  30
    end values
  end function pull
  begin property specification for material polysilicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model elastic
  end property specification for material polysilicon
  begin solid section hex8
  end solid section hex8
  begin finite element model clamp
    begin generated box counter
      origin = -10 -2 -2 um
      size = 220 14 2 um
      intervals = 11 1 1
    end generated box counter
    begin generated box foot
      origin = 0 0 0 um
      size = 200 10 2 um
      intervals = 20 1 1
    end generated box foot
    begin parameters for block counter
      material = polysilicon
      section = hex8
    end parameters for block counter
    begin parameters for block foot
      material = polysilicon
      section = hex8
    end parameters for block foot
  end finite element model clamp
  begin presto procedure clamp_and_pull
    begin time control
      termination time = 1200 ns
    end time control
    begin presto region main
      use finite element model clamp
      mass damping coefficient = 5e7 1/s
      begin fixed displacement
        node set = counter_all
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = foot_all
        components = y
      end fixed displacement
      begin pressure
        side set = foot_zmax
        function = ramp
        scale factor = 50000 Pa   # NORMAL PRESSURE: N / (200 um x 10 um); 50 kPa = 100 uN
      end pressure
      begin prescribed displacement
        node set = foot_xmin
        component = x
        function = pull
      end prescribed displacement
      begin contact definition clamp_contact
        contact surface foot_face contains foot_zmin
        contact surface counter_face contains counter_zmax
        begin interaction rough_foot
          surfaces = foot_face counter_face
          model = rough surface
          summit density = 3.796e16 1/m^2
          summit radius = 14.71 nm
          summit height deviation = 1.536 nm
          composite modulus = 84.1 GPa
          work of adhesion = 0.1 J/m^2
          junction strength = 1 GPa
          junction reference speed = 0.001 m/s
          mean plane offset = 9.2 nm
        end interaction rough_foot
      end contact definition clamp_contact
      begin history output hist
        step increment = 20
        reaction force = foot_xmin
        mean displacement = foot_zmin foot_xmin
      end history output hist
    end presto region main
  end presto procedure clamp_and_pull
end sierra clamp_friction
