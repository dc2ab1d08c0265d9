// SPDX-License-Identifier: MIT
// tribex_write_deck_mesh DECK OUT.exo|OUT.msh [--unused-node|--msh22]: the mesh of DECK's region (build_mesh,
// as a run builds it) written as Exodus II (or, for a name ending .msh, as binary gmsh MSH 4.1; --msh22: ASCII
// MSH 2.2, which the set-up does not read in slices), so that the tests
// of the read in slices (`set-up = distributed`, solver/parallel/file_slice_source.hpp) run a deck's mesh from a
// file without a file over the repository's size limit. --unused-node adds one node no element uses.
#include <cstdio>
#include <exception>
#include <string>

#include "inputs/diagnostics.hpp"
#include "mesh/exodus_io.hpp"
#include "mesh/gmsh_io.hpp"
#include "solver/model.hpp"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: tribex_write_deck_mesh DECK OUT.exo|OUT.msh [--unused-node|--msh22]\n");
    return 2;
  }
  try {
    tribex::mesh::Mesh m = tribex::solver::build_mesh(tribex::inputs::parse_deck_file(argv[1]));
    if (argc > 3 && std::string(argv[3]) == "--unused-node")
      for (int i = 0; i < 3; ++i) m.coordinates.push_back(m.coordinates[static_cast<std::size_t>(i)] - 1e-6);
    const std::string out = argv[2];
    const bool msh22 = argc > 3 && std::string(argv[3]) == "--msh22";
    if (out.size() > 4 && out.substr(out.size() - 4) == ".msh") tribex::mesh::write_gmsh(m, out, !msh22, msh22 ? 2.2 : 4.1);
    else tribex::mesh::write_exodus(m, out);
    std::printf("wrote %s: %d nodes, %d hex8 elements\n", argv[2], m.node_count(), m.element_count());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
