# counts_indenter_4m.i -- counts_indenter.i scaled up for issue 57's counts on a generated model of at
# least 4 M elements (tools/bench/README.md, "Counts per rank, results output on, at scale"): a
# 160 x 160 x 160 nm silicon block of 1 nm hex8 (4,096,000 elements, mean quadrature, elastic) with a
# 48 x 48 x 16 nm flat indenter (36,864 elements) resting on its top centre, pushed down at 1 m/s;
# frictionless node-to-face contact, indenter bottom on block top; 4,132,864 elements in all.
# 0.3 ps = 5 steps, as counts_indenter.i: the counts do not need more, and set-up dominates the run.
# No field output (tools/bench/partition_methods.py --results h5 adds one); history every step.
# About 4 GB on one rank with results.h5 output: size the rank counts to the machine's memory.
#
# Run:    /usr/bin/python3 tools/bench/partition_methods.py build/bin/tribex tools/bench/counts_indenter_4m.i OUT \
#             --ranks 4 16 64 --methods distributed --results h5
begin sierra counts_indenter_4m
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
      size = 160 160 160 nm
      intervals = 160 160 160
    end generated box block
    begin generated box indenter
      origin = 56 56 160 nm
      size = 48 48 16 nm
      intervals = 48 48 16
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
end sierra counts_indenter_4m
