# rigid_slide_nodeset.i -- written by make_decks.py (edit that, not this file).
# Force-controlled sliding of a silicon sphere (R = 27 nm) on a SAM-coated silicon flat (coating 1.6 nm,
# E = 8 GPa), junction model (W = 0.05 J/m^2, tau* = 194 MPa): the tip top loaded with `prescribed force` on its node set (equal shares per node), as before rigid bodies.
# 0 - 80 ps: normal load ramped to 100 nN (cycloidal); 120 - 440 ps: the tip top slides 3 nm
# in +x at 10 m/s (cycloidal 40 ps speed ramp); y of the tip top held.
#
# Run:    build/bin/tribex run verification/rigid_slide/rigid_slide_nodeset.i -o rigid_slide_nodeset_output
# Check:  /usr/bin/python3 verification/rigid_slide/compare.py rigid_slide_nodeset_output  (README.md)
# END: the termination time. CI runs the rigid deck with --set "END=220 ps" (0.8 nm of slide, README.md
# "The CI run"): the rocking it guards against shows long before the 3 nm.
{END = 460.0 ps}
begin sierra rigid_slide_nodeset
  begin function load
    type = piecewise linear
    abscissa unit = ps
    begin values
          0.0  0.000000
         10.0  0.012460
         20.0  0.090845
         30.0  0.262460
         40.0  0.500000
         50.0  0.737540
         60.0  0.909155
         70.0  0.987540
         80.0  1.000000
       1000.0  1.000000
    end values
  end function load
  begin function slide
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0  0.000000
        120.0  0.000000
        125.0  0.000157
        130.0  0.002368
        135.0  0.010828
        140.0  0.029736
        145.0  0.060828
        150.0  0.102368
        155.0  0.150157
        160.0  0.200000
        440.0  3.000000
       1000.0  3.000000
    end values
  end function slide
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin property specification for material sam
    density = 1000 kg/m^3
    begin parameters for model elastic
      youngs modulus = 8 GPa
      poissons ratio = 0.4
    end parameters for model elastic
  end property specification for material sam
  begin solid section hex8
    formulation = fully_integrated
  end solid section hex8
  begin finite element model asperity
    begin generated asperity
      radius = 27 nm
      tip width = 24 nm
      tip height = 13 nm
      substrate width = 40 nm
      substrate depth = 20 nm
      element size = 0.8 nm
      fine half width = 9.6 nm
      fine depth = 3.2 nm
      grading ratio = 1.4
      coating thickness = 1.6 nm
      coating layers = 2
    end generated asperity
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
    begin parameters for block coating
      material = sam
      section = hex8
    end parameters for block coating
  end finite element model asperity
  begin presto procedure load_and_slide
    begin time control
      termination time = {END}
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = tip_top
        components = y
      end fixed displacement
      begin prescribed force
        node set = tip_top
        component = z
        function = load
        scale factor = -100.0 nN
      end prescribed force
      begin prescribed displacement
        node set = tip_top
        component = x
        function = slide
      end prescribed displacement
      begin contact definition tip_on_flat
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        contact axis = 0 0 0 0 0 1 nm
        begin interaction sphere_flat
          surfaces = flat tip     # the coating is the softer side: slave
          model = junction
          work of adhesion = 0.05 J/m^2
          equilibrium separation = 0.3 nm
          adhesion cutoff = 6 nm
          junction strength = 194 MPa
          junction reference speed = 0.1 m/s
          junction gap tolerance = 0 nm
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 2 ps
        reaction force = substrate_bottom
        mean displacement = tip_top tip_apex
      end history output hist
      begin results output fields
        time increment = 20 ps
        nodal variables = displacement
      end results output fields
    end presto region main
  end presto procedure load_and_slide
end sierra rigid_slide_nodeset
