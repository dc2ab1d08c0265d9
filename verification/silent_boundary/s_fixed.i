# s_fixed.i -- the same S wave on a fixed end (control: reflects)
#
# Run:    build/bin/tribex run verification/silent_boundary/s_fixed.i -o s_fixed_output
# Check:  /usr/bin/python3 verification/silent_boundary/compare.py --case s_fixed s_fixed_output/history.csv
#
#   col_zmax  <- x-velocity half-sine pulse, 1 m/s peak, 4 ps long (about 35 elements of P wave)
#   +--+
#   |  |  1 nm x 1 nm x 200 nm silicon column, 200 hex8; every node held in y z
#   +--+
#   col_zmin  fixed: reflects everything
#
# The pulse enters, runs to the bottom and reflects;
# at 52 ps the reflected part is back inside the column but has not reached the top, so
# (kinetic + internal energy) / external work is the reflected energy fraction.
begin sierra s_fixed
  include common.inc
  begin presto procedure pulse_run
    begin time control
      termination time = 52 ps
    end time control
    begin presto region column
      use finite element model column
      begin fixed displacement
        node set = col_xmin
        components = y z
      end fixed displacement
      begin fixed displacement
        node set = col_xmax
        components = y z
      end fixed displacement
      begin prescribed velocity
        node set = col_zmax
        component = x
        function = pulse
        scale factor = -1
      end prescribed velocity
      begin fixed displacement
        node set = col_zmin
        components = x
      end fixed displacement
      begin history output energies
        step increment = 10
      end history output energies
    end presto region column
  end presto procedure pulse_run
end sierra s_fixed
