# counts_indenter_wide.i -- counts_indenter.i with a 90 x 90 x 10 nm indenter (81,000 elements)
# instead of 30 x 30 x 10: a contact zone nine times larger (8,281 slave nodes), so that each rank's
# patch of it is several region reaches wide at 4 to 16 ranks: the contact bytes per rank in the
# regime where the band around a patch falls with its perimeter (tools/bench/README.md "Counts per
# rank"). Block, push, contact and output as in counts_indenter.i.
#
# Run:    /usr/bin/python3 tools/bench/rank_counts.py build/bin/tribex tools/bench/counts_indenter_wide.i OUT --ranks 1 4 8 16 --run
begin sierra counts_indenter_wide
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
      origin = 5 5 100 nm
      size = 90 90 10 nm
      intervals = 90 90 10
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
end sierra counts_indenter_wide
