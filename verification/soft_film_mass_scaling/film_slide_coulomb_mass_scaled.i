# Soft film under mass scaling (issue 51; README.md): a silicon sphere R = 15 nm pressed 0.56 nm into a
# 1.5 nm film (E_c 5 GPa, nu_c 0.35, 1100 kg/m^3) on silicon, held, slid 3 nm and withdrawn, with Coulomb
# friction (mu 0.3) and Lennard-Jones adhesion (W 0.06 J/m^2, z0 0.3 nm), and the fast options the docs
# show (fully integrated skin and film, mean quadrature elsewhere) and
# `begin mass scaling` at twice the step. Its unscaled twin is film_slide_coulomb.i; compare.py checks the energy
# balance, the contact force's steadiness in the hold (520-550 ps) and its mean against the twin's.
# END: the termination time. CI runs these decks with --set "END=552 ps", to the end of the hold that
# compare.py checks (README.md "The CI runs"); the withdrawal to 800 ps runs under `slow`.
{END = 800 ps}
begin sierra film_slide_coulomb
  begin function push
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.0   0.00000
          10.0   0.02131
          20.0   0.08201
          30.0   0.17285
          40.0   0.28000
          50.0   0.38715
          60.0   0.47799
          70.0   0.53869
          80.0   0.56000
         550.0   0.56000
         800.0  -1.00000
    end values
  end function push
  begin function slide
    type = piecewise linear
    abscissa unit = ps
    ordinate unit = nm
    begin values
           0.0   0.00000
         120.0   0.00000
         140.0   0.00246
         160.0   0.01935
         180.0   0.06372
         200.0   0.14590
         220.0   0.27254
         240.0   0.44590
         260.0   0.66372
         280.0   0.91935
         300.0   1.20246
         320.0   1.50000
         340.0   1.79754
         360.0   2.08065
         380.0   2.33628
         400.0   2.55410
         420.0   2.72746
         440.0   2.85410
         460.0   2.93628
         480.0   2.98065
         500.0   2.99754
         520.0   3.00000
    end values
  end function slide
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin property specification for material film
    density = 1100 kg/m^3
    begin parameters for model elastic
      youngs modulus = 5 GPa
      poissons ratio = 0.35
    end parameters for model elastic
  end property specification for material film
  begin solid section full
    formulation = fully_integrated
  end solid section full
  begin solid section mq
    formulation = mean_quadrature
  end solid section mq
  begin finite element model asperity
    begin generated asperity
      radius = 15 nm
      tip width = 16 nm
      tip height = 10.5 nm
      substrate width = 40 nm
      substrate depth = 20 nm
      element size = 1 nm
      fine half width = 7.5 nm
      fine depth = 2.5 nm
      grading ratio = 1.3
      coating thickness = 1.5 nm
      coating layers = 3
    end generated asperity
    begin surface layer block tip_skin
      from block = tip
      surface = tip_surface
      layers = 2
    end surface layer block tip_skin
    begin parameters for block tip
      material = silicon
      section = mq
    end parameters for block tip
    begin parameters for block tip_skin
      material = silicon
      section = full
    end parameters for block tip_skin
    begin parameters for block coating
      material = film
      section = full
    end parameters for block coating
    begin parameters for block substrate
      material = silicon
      section = mq
    end parameters for block substrate
  end finite element model asperity
  begin presto procedure press_slide_pull
    begin time control
      termination time = {END}
    end time control
    begin presto region main
      use finite element model asperity
      mass damping coefficient = 1e11 1/s
      quasi static = on
      begin mass scaling
        largest factor = 2
      end mass scaling
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
      begin contact definition tip_on_film
        contact surface tip contains tip_surface
        contact surface flat contains substrate_top
        begin interaction sphere_flat
          surfaces = flat tip
          model = coulomb
          static friction coefficient = 0.3
          work of adhesion = 0.06 J/m^2
          equilibrium separation = 0.3 nm
        end interaction sphere_flat
      end contact definition tip_on_film
      begin history output hist
        time increment = 2 ps
        reaction force = tip_top substrate_bottom
        mean displacement = tip_top tip_apex
      end history output hist
    end presto region main
  end presto procedure press_slide_pull
end sierra film_slide_coulomb
