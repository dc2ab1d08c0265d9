# A gmsh mesh, materials from an included file, Sierra-style continuation and delimiters.
begin sierra with_include
  include materials_part.inc
  begin solid section sec
  end solid section sec
  begin finite element model m
    database name = ../mesh/tip.msh
    begin parameters for block tip
      material is copper
      section sec
    end parameters for block tip
  end finite element model m
  begin presto procedure p
    begin time control
      termination time \
        = 2 ns
    end time control
    begin presto region r
      use finite element model m
      begin history output h
        time increment = 1 ps
        reaction force are tip_top
      end history output h
    end presto region r
  end presto procedure p
end sierra with_include
