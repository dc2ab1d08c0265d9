# silent_box.i -- a pressure pulse absorbed by a silent (non-reflecting) boundary.
#
# Run:    build/bin/tribex run inputs/examples/silent_box.i -o silent_box_output
#         /usr/bin/python3 tools/plot/plot_history.py silent_box_output/history.csv silent_box.png \
#             --columns kinetic_energy,internal_energy,silent_boundary_dissipation,external_work
# View:   open silent_box_output/results.xdmf in ParaView (displacement, velocity, stress)
#
#                 box_zmax: pressure pulse, sin^2 over 2 ps, 200 MPa peak
#          +-------------------+
#         /                   /|   20 nm x 20 nm x 40 nm silicon, 10 x 10 x 40 hex8
#        +-------------------+ |   rollers on the four sides (x on box_xmin/xmax, y on box_ymin/ymax)
#        |                   | |
#        |                   | +
#        |                   |/
#        +-------------------+
#                 box_zmin: silent boundary (Lysmer-Kuhlemeyer dashpots, a = b = 1)
#
# What it shows: the pulse enters through the top (external work), travels down at c_d, and leaves
# through the silent bottom: kinetic + internal energy return to ~0 and the silent-boundary
# dissipation equals the work put in. Replace the silent boundary by a fixed bottom and the pulse
# bounces forever.
begin sierra silent_box
  begin function pulse
    type = piecewise linear
    abscissa unit = ps
    begin values
       0.00  0.000000
       0.10  0.024472
       0.20  0.095492
       0.30  0.206107
       0.40  0.345492
       0.50  0.500000
       0.60  0.654508
       0.70  0.793893
       0.80  0.904508
       0.90  0.975528
       1.00  1.000000
       1.10  0.975528
       1.20  0.904508
       1.30  0.793893
       1.40  0.654508
       1.50  0.500000
       1.60  0.345492
       1.70  0.206107
       1.80  0.095492
       1.90  0.024472
       2.00  0.000000
      1000.0 0.0
    end values
  end function pulse

  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model elastic
  end property specification for material silicon

  begin solid section hex8
    formulation = mean_quadrature
    hourglass stiffness = 0.05
  end solid section hex8

  begin finite element model slab
    begin generated box box
      size = 20 20 40 nm
      intervals = 10 10 40
    end generated box box
    begin parameters for block box
      material = silicon
      model = elastic
      section = hex8
    end parameters for block box
  end finite element model slab

  begin presto procedure absorb
    begin time control
      termination time = 12 ps
    end time control
    begin presto region slab
      use finite element model slab
      begin fixed displacement
        node set = box_xmin
        components = x
      end fixed displacement
      begin fixed displacement
        node set = box_xmax
        components = x
      end fixed displacement
      begin fixed displacement
        node set = box_ymin
        components = y
      end fixed displacement
      begin fixed displacement
        node set = box_ymax
        components = y
      end fixed displacement
      begin pressure
        side set = box_zmax
        function = pulse
        scale factor = 200 MPa
      end pressure
      begin silent boundary
        side set = box_zmin
      end silent boundary
      begin history output energies
        time increment = 0.05 ps
      end history output energies
      begin results output fields
        time increment = 0.5 ps
        nodal variables = displacement velocity
        element variables = stress
      end results output fields
    end presto region slab
  end presto procedure absorb
end sierra silent_box
