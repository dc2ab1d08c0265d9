# counts_indenter.i -- the model of the per-rank counts table (issue 25; tools/bench/README.md,
# "Counts per rank"): a 100 x 100 x 100 nm silicon block of 1 nm hex8 (1,000,000 elements, mean
# quadrature, elastic) with a 30 x 30 x 10 nm flat indenter (9,000 elements) resting on its top
# centre, pushed down at 1 m/s; frictionless node-to-face contact, indenter bottom on block top.
# 0.3 ps = 5 steps: the counts (bytes and pairs per step, peak RSS) do not need more, and set-up
# dominates the run. No field output; history every step.
#
# Run:    mpirun -np 4 --oversubscribe build/bin/tribex run tools/bench/counts_indenter.i -o OUT
begin sierra counts_indenter
  begin function push
    type = piecewise linear
    abscissa unit = ps
    begin values
      0.0   1.0
      100.0 1.0
    end values
  end function push
  begin property specification for material silicon
    density = 2330 kg/m^3
    begin parameters for model elastic
      youngs modulus = 161 GPa
      poissons ratio = 0.23
    end parameters for model elastic
  end property specification for material silicon
  begin solid section hex8
    formulation = mean_quadrature
  end solid section hex8
  begin finite element model blocks
    begin generated box block
      size = 100 100 100 nm
      intervals = 100 100 100
    end generated box block
    begin generated box indenter
      origin = 35 35 100 nm
      size = 30 30 10 nm
      intervals = 30 30 10
    end generated box indenter
    begin parameters for block block
      material = silicon
      section = hex8
    end parameters for block block
    begin parameters for block indenter
      material = silicon
      section = hex8
    end parameters for block indenter
  end finite element model blocks
  begin presto procedure push
    begin time control
      termination time = 0.3 ps
    end time control
    begin presto region main
      use finite element model blocks
      begin fixed displacement
        node set = block_zmin
        components = x y z
      end fixed displacement
      begin prescribed velocity
        node set = indenter_zmax
        component = z
        function = push
        scale factor = -1
      end prescribed velocity
      begin contact definition punch
        contact surface punch_face contains indenter_zmin
        contact surface top contains block_zmax
        begin interaction punch_on_top
          surfaces = punch_face top
          model = frictionless
        end interaction punch_on_top
      end contact definition punch
      begin history output hist
        step increment = 1
        reaction force = indenter_zmax block_zmin
      end history output hist
    end presto region main
  end presto procedure push
end sierra counts_indenter
