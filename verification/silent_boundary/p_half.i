# p_half.i -- P wave on a half-strength dashpot (a = 0.5): amplitude reflection (1-a)/(1+a) = 1/3
#
# Run:    build/bin/tribex run verification/silent_boundary/p_half.i -o p_half_output
# Check:  /usr/bin/python3 verification/silent_boundary/compare.py --case p_half p_half_output/history.csv
#
#   col_zmax  <- z-velocity half-sine pulse, 1 m/s peak, 4 ps long (about 35 elements of P wave)
#   +--+
#   |  |  1 nm x 1 nm x 200 nm silicon column, 200 hex8; every node held in x y
#   +--+
#   col_zmin  dashpots with a = 0.5, b = 1
#
# The pulse enters, runs to the bottom and leaves through the dashpots;
# at 32 ps the reflected part is back inside the column but has not reached the top, so
# (kinetic + internal energy) / external work is the reflected energy fraction.
begin sierra p_half
  include common.inc
  begin presto procedure pulse_run
    begin time control
      termination time = 32 ps
    end time control
    begin presto region column
      use finite element model column
      begin fixed displacement
        node set = col_xmin
        components = x y
      end fixed displacement
      begin fixed displacement
        node set = col_xmax
        components = x y
      end fixed displacement
      begin prescribed velocity
        node set = col_zmax
        component = z
        function = pulse
        scale factor = -1
      end prescribed velocity
      begin silent boundary
        side set = col_zmin
        normal coefficient = 0.5
        tangential coefficient = 1
      end silent boundary
      begin history output energies
        step increment = 10
      end history output energies
    end presto region column
  end presto procedure pulse_run
end sierra p_half
