# contact_patch.i -- contact patch test: two flat blocks with non-matching meshes pressed together.
#
# Run:    build/bin/tribex run verification/contact_patch/contact_patch.i -o contact_patch_output
# Check:  /usr/bin/python3 verification/contact_patch/compare.py contact_patch_output
#
#            upper_zmax: pressed down by 0.05 nm (1 % strain), then held
#        +-------------+   block `upper`: 10 x 10 x 5 nm, 3 x 3 x 2 hex8
#        +-------------+   upper_zmin (slave) on lower_zmax (master): non-matching faces
#        +-------------+   block `lower`: 10 x 10 x 5 nm, 4 x 4 x 2 hex8
#            lower_zmin: fixed in z
#   Symmetry planes x = 0 (x fixed) and y = 0 (y fixed) for both blocks; x = 10, y = 10 free, so the
#   exact solution is a uniform uniaxial stress and a uniform contact pressure.
#   `enforcement = mortar`: segment-to-segment contact, exact for this test (node to face: 5.7 % spread).
begin sierra contact_patch
  begin function squeeze
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
      0    0
      40   0.05
      400  0.05
    end values
  end function squeeze
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
      size = 10 10 5 nm
      intervals = 4 4 2
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
  begin presto procedure press
    begin time control
      termination time = 400 ps
    end time control
    begin presto region main
      use finite element model blocks
      mass damping coefficient = 2e11 1/s
      begin fixed displacement
        node set = lower_zmin
        components = z
      end fixed displacement
      begin fixed displacement
        node set = lower_xmin
        components = x
      end fixed displacement
      begin fixed displacement
        node set = lower_ymin
        components = y
      end fixed displacement
      begin fixed displacement
        node set = upper_xmin
        components = x
      end fixed displacement
      begin fixed displacement
        node set = upper_ymin
        components = y
      end fixed displacement
      begin prescribed displacement
        node set = upper_zmax
        component = z
        function = squeeze
        scale factor = -1
      end prescribed displacement
      begin contact definition interface
        contact surface upper_face contains upper_zmin
        contact surface lower_face contains lower_zmax
        begin interaction flat_on_flat
          surfaces = upper_face lower_face
          symmetric = on
          enforcement = mortar
        end interaction flat_on_flat
      end contact definition interface
      begin history output hist
        step increment = 50
        reaction force = upper_zmax lower_zmin
      end history output hist
      begin results output fields
        time increment = 100 ps
        nodal variables = displacement contact_traction contact_status contact_pressure gap
        element variables = stress von_mises
      end results output fields
    end presto region main
  end presto procedure press
end sierra contact_patch
