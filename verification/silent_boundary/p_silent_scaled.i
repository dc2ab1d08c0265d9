# p_silent_scaled.i -- p_silent.i with mass scaling on the column (density factor 4): the silent
# boundary's dashpots keep the physical impedance rho c, the scaled elements' is sqrt(4) rho c = 2 rho c,
# so the boundary reflects (2 - 1)/(2 + 1) = 1/3 of the amplitude, 1/9 of the energy (docs/theory.md
# 1.4.1, 4.4), as p_half.i does with a = 0.5. The run warns at set-up (scaled_silent_boundary, naming
# that 1/3); this deck checks the warning's figure.
#
# Run:    build/bin/tribex run verification/silent_boundary/p_silent_scaled.i -o p_silent_scaled_output
# Check:  /usr/bin/python3 verification/silent_boundary/compare.py --case p_silent_scaled p_silent_scaled_output/history.csv
#
# The scaled column carries the pulse at half the speed: at 64 ps (twice p_silent's end) the reflected
# part is back inside the column but has not reached the top.
begin sierra p_silent_scaled
  include common.inc
  begin presto procedure pulse_run
    begin time control
      termination time = 64 ps
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
      begin mass scaling
        largest factor = 2                 # target step 2 x the unscaled: density factor 4 everywhere
        maximum added mass fraction = 4    # the whole column is scaled: +300 %
      end mass scaling
      begin silent boundary
        side set = col_zmin
        normal coefficient = 1
        tangential coefficient = 1
      end silent boundary
      begin history output energies
        step increment = 10
      end history output energies
    end presto region column
  end presto procedure pulse_run
end sierra p_silent_scaled
