# exodus_bad_mesh.i -- a deck whose mesh is the Exodus II file bad_mesh.exo beside it, which the
# CLI tests cli_exodus_mesh_* (tests/cli/CMakeLists.txt) make missing, garbage or all-tetrahedra:
# each must be exit code 2 with one line naming the file.
begin sierra exodus_bad_mesh
  begin property specification for material steel
    density = 7850 kg/m^3
    begin parameters for model elastic
      youngs modulus = 200 GPa
      poissons ratio = 0.3
    end parameters for model elastic
  end property specification for material steel
  begin solid section hex8
  end solid section hex8
  begin finite element model body
    database name = bad_mesh.exo
    begin parameters for block block_10
      material = steel
      model = elastic
      section = hex8
    end parameters for block block_10
  end finite element model body
  begin presto procedure p
    begin time control
      termination time = 1 ps
    end time control
    begin presto region r
      use finite element model body
    end presto region r
  end presto procedure p
end sierra exodus_bad_mesh
