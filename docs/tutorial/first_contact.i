# first_contact.i -- the deck of docs/tutorial.md: a silicon sphere (R = 27 nm) pressed 0.8 nm into a
# silicon flat, slid 1.5 nm and pulled off, with Lennard-Jones adhesion and Coulomb friction. Coarse
# (1.6 nm elements, about 3 s on one core): a deck to learn on, not a verification case.
#
# Run:    build/bin/tribex run docs/tutorial/first_contact.i -o first_contact_output
# Vary:   build/bin/tribex run docs/tutorial/first_contact.i -o w010 --set W=0.10
{W = 0.05 J/m^2}     # work of adhesion
{MU = 0.3}           # Coulomb friction coefficient
{R = 27 nm}          # sphere radius
begin sierra first_contact
  begin function push          # tip_top down (z, scale -1): press, hold, pull off
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0    0.00000
          3.0    0.00516
          6.0    0.03891
          9.0    0.11891
         12.0    0.24516
         15.0    0.40000
         18.0    0.55484
         21.0    0.68109
         24.0    0.76109
         27.0    0.79484
         30.0    0.80000
        100.0    0.80000
        104.0    0.78194
        108.0    0.66382
        112.0    0.38382
        116.0   -0.05806
        120.0   -0.60000
        124.0   -1.14194
        128.0   -1.58382
        132.0   -1.86382
        136.0   -1.98194
        140.0   -2.00000
       1000.0   -2.00000
    end values
  end function push
  begin function slide          # tip_top along x: slide during the hold
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
          0.0    0.00000
         40.0    0.00000
         45.0    0.00968
         50.0    0.07295
         55.0    0.22295
         60.0    0.45968
         65.0    0.75000
         70.0    1.04032
         75.0    1.27705
         80.0    1.42705
         85.0    1.49032
         90.0    1.50000
       1000.0    1.50000
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
    formulation = fully_integrated   # node-to-face contact on one-point elements excites hourglass modes
  end solid section hex8

  begin finite element model asperity
    begin generated asperity
      radius = {R}
      tip width = 32 nm
      tip height = 26 nm
      substrate width = 60 nm
      substrate depth = 30 nm
      element size = 1.6 nm
      fine half width = 6.4 nm
      fine depth = 3.2 nm
      grading ratio = 1.35
    end generated asperity
    begin parameters for block tip
      material = silicon
      section = hex8
    end parameters for block tip
    begin parameters for block substrate
      material = silicon
      section = hex8
    end parameters for block substrate
  end finite element model asperity

  begin presto procedure contact_cycle
    begin time control
      termination time = 140 ps
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 5e11 1/s   # quasi-static: damps the ringing of the pull-off
      begin fixed displacement
        node set = substrate_bottom
        components = x y z
      end fixed displacement
      begin fixed displacement
        node set = tip_top
        components = y
      end fixed displacement
      begin prescribed displacement
        node set = tip_top
        component = z
        function = push
        scale factor = -1
      end prescribed displacement
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
          surfaces = tip flat
          model = coulomb
          static friction coefficient = {MU}
          work of adhesion = {W}
          equilibrium separation = 0.3 nm
        end interaction sphere_flat
      end contact definition tip_on_flat
      begin history output hist
        time increment = 1 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex
      end history output hist
      begin results output fields
        time increment = 10 ps
        nodal variables = displacement contact_pressure contact_status gap
        element variables = von_mises
      end results output fields
    end presto region main
  end presto procedure contact_cycle
end sierra first_contact
