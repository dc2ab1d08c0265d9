# rigid_punch.i -- a rigid flat circular punch (radius a = 10 nm) pressed 0.1 nm into an elastic
# cylinder (R = H = L a), the punch being a rigid body made of the top-surface nodes r <= a
# (a kinematic coupling: the nodes move with the body in x, y and z, so the punch is bonded, "welded").
# The mesh punch.msh beside this deck is written by make_mesh.py (run_punch.py copies this deck
# next to it; verification/rigid_punch/README.md).
#
# Reference: Mossakovskii's welded flat punch on a half-space, K = 4 G a ln(3 - 4 nu) / (1 - 2 nu)
# (the frictionless Boussinesq/Sneddon punch K = 2 a E / (1 - nu^2) times (1 - nu) ln(3 - 4 nu) / (1 - 2 nu),
# 1.0287 at nu = 0.3), corrected for the finite cylinder (compare.py).
#
#           punch: rigid body, z driven by 'press' (cycloidal ramp to 0.1 nm in 150 ps, then held)
#        +----====----+  top: free outside r = a
#        |            |  side: free
#        |  elastic   |
#        +------------+  bottom: fixed
{L = 10}   # R = H = L a: run_punch.py --domain L sets it (--set L=...), with the mesh
begin sierra rigid_punch
  begin function press
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.0  0.0000000
          10.0  0.0001933
          20.0  0.0015058
          30.0  0.0048635
          40.0  0.0108384
          50.0  0.0195501
          60.0  0.0306451
          70.0  0.0433576
          80.0  0.0566424
          90.0  0.0693549
         100.0  0.0804499
         110.0  0.0891616
         120.0  0.0951365
         130.0  0.0984942
         140.0  0.0998067
         150.0  0.1000000
         400.0  0.1000000
    end values
  end function press

  begin property specification for material block_material
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 100 GPa
      poissons ratio = 0.3
    end parameters for model elastic
  end property specification for material block_material

  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8

  begin finite element model cylinder
    database name = punch.msh
    begin parameters for block block
      material = block_material
      section = hex8
    end parameters for block block
  end finite element model cylinder

  begin presto procedure press
    begin time control
      termination time = {25e-12 * L}   # 250 ps at L = 10: settled from 160 ps on
    end time control
    begin presto region main
      use finite element model cylinder
      mass damping coefficient = {1.5e12 / L}   # 1/s, about critical for the cylinder's first modes
      begin rigid body punch_body
        node set = punch
        rotation = fixed
      end rigid body punch_body
      begin fixed displacement
        node set = bottom
        components = x y z
      end fixed displacement
      begin prescribed displacement
        rigid body = punch_body
        component = z
        function = press
        scale factor = -1
      end prescribed displacement
      begin history output hist
        time increment = 5 ps
      end history output hist
      begin restart output           # for the restart test (CMakeLists.txt): --stop-at-step writes one
        wall time increment = 600 s
      end restart output
    end presto region main
  end presto procedure press
end sierra rigid_punch
