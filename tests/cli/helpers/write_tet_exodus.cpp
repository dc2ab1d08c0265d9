// SPDX-License-Identifier: MIT
// write_tet_exodus FILE: a one-tetrahedron Exodus II file (block id 10, TETRA4), for the CLI test
// that tribex refuses a mesh with non-hex blocks (tests/cli/CMakeLists.txt, cli_exodus_mesh_*).
#include <exodusII.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_tet_exodus FILE\n");
    return 2;
  }
  int comp = 8, io = 8;
  const int exo = ex_create(argv[1], EX_CLOBBER | EX_LARGE_MODEL, &comp, &io);
  if (exo < 0) return 1;
  const double x[4] = {0, 1, 0, 0}, y[4] = {0, 0, 1, 0}, z[4] = {0, 0, 0, 1};
  const int conn[4] = {1, 2, 3, 4};
  const bool ok = ex_put_init(exo, "one tet", 3, 4, 1, 1, 0, 0) >= 0 && ex_put_coord(exo, x, y, z) >= 0 &&
                  ex_put_block(exo, EX_ELEM_BLOCK, 10, "TETRA4", 1, 4, 0, 0, 0) >= 0 &&
                  ex_put_conn(exo, EX_ELEM_BLOCK, 10, conn, nullptr, nullptr) >= 0;
  return ex_close(exo) >= 0 && ok ? 0 : 1;
}
