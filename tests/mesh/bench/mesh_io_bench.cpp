// SPDX-License-Identifier: MIT
// Timing of the mesh layer: generate_box, validate, write_gmsh, read_gmsh on n^3 boxes.
// Prints a CSV table (best of `repeats` runs, wall seconds); asserts nothing about time.
//   bench_mesh_io [n ...]      default: 50 100
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include "mesh/box.hpp"
#include "mesh/gmsh_io.hpp"
#include "mesh/mesh_error.hpp"

namespace {

template <class F>
double best_of(int repeats, F&& f) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace tribex::mesh;
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::stoi(argv[i]));
  if (sizes.empty()) sizes = {50, 100};
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("tribex_bench_mesh_" + std::to_string(::getpid()) + ".msh");
  std::printf("n,elements,nodes,generate_box_s,validate_s,write_gmsh_s,read_gmsh_s,msh_bytes\n");
  try {
    for (int n : sizes) {
      BoxSpec spec;
      spec.intervals = {n, n, n};
      spec.grade_toward = "zmax";
      spec.grading_ratio = 1.02;
      Mesh mesh;
      const double t_gen = best_of(5, [&] { mesh = generate_box(spec); });
      const double t_val = best_of(3, [&] { validate(mesh, "bench"); });
      const double t_write = best_of(2, [&] { write_gmsh(mesh, file.string()); });
      Mesh back;
      const double t_read = best_of(2, [&] { back = read_gmsh(file.string()); });
      if (back.element_count() != mesh.element_count() || back.coordinates != mesh.coordinates) {
        std::fprintf(stderr, "bench_mesh_io: round trip differs at n = %d\n", n);
        return 1;
      }
      std::printf("%d,%d,%d,%.4f,%.4f,%.4f,%.4f,%llu\n", n, mesh.element_count(), mesh.node_count(), t_gen, t_val,
                  t_write, t_read, static_cast<unsigned long long>(std::filesystem::file_size(file)));
    }
  } catch (const MeshError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  std::filesystem::remove(file);
  return 0;
}
