# counts_box_output.i -- rank 0's memory with field output on (issue 57 scope 3; tools/bench/README.md
# "Counts per rank, results output on"): scaling_block.i's silicon block of 1 nm hex8 (mean
# quadrature, elastic) at 80 x 80 x 80 (512,000 elements, 531,441 nodes), bottom fixed, top pulled
# at 1 m/s; 0.3 ps = 5 steps; results.h5 at every step (displacement, velocity, stress: 62.4 MB of
# values per output, stress stored as 9 components), so set-up and the output steps are in the peak RSS.
#
# Run:    /usr/bin/python3 tools/bench/rank_counts.py build/bin/tribex tools/bench/counts_box_output.i OUT --ranks 1 4 --run
begin sierra counts_box_output
  begin function pull
    type = piecewise linear
    abscissa unit = ps
    begin values
      0.0   1.0
      100.0 1.0
    end values
  end function pull
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 160 GPa
      poissons ratio = 0.22
    end parameters for model elastic
  end property specification for material silicon
  begin solid section hex8
    formulation = mean_quadrature
  end solid section hex8
  begin finite element model block
    begin generated box block
      size = 80 80 80 nm
      intervals = 80 80 80
    end generated box block
    begin parameters for block block
      material = silicon
      model = elastic
      section = hex8
    end parameters for block block
  end finite element model block
  begin presto procedure pull
    begin time control
      termination time = 0.3 ps
    end time control
    begin presto region block
      use finite element model block
      begin fixed displacement
        node set = block_zmin
        components = x y z
      end fixed displacement
      begin prescribed velocity
        node set = block_zmax
        component = z
        function = pull
      end prescribed velocity
      begin history output h
        step increment = 1
      end history output h
      begin results output fields
        step increment = 1
        nodal variables = displacement velocity
        element variables = stress
      end results output fields
    end presto region block
  end presto procedure pull
end sierra counts_box_output
