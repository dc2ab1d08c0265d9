// SPDX-License-Identifier: MIT
// A hand-built hex8 box and the analytic sample fields used by the output tests, the sample writer
// for the ParaView check (check_xdmf_paraview.py repeats these formulas) and the benchmark.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "solver/output/results_writer.hpp"

namespace tribex::test {

/// nx x ny x nz unit cubes; node (i,j,k) = i + (nx+1)(j + (ny+1)k) at (i, j, k) m; element
/// (i,j,k) = i + nx(j + ny k). Elements with k < nz/2 form block "substrate", the rest "asperity"
/// (k-major numbering keeps each block a contiguous range).
inline mesh::Mesh make_hand_box(int nx, int ny, int nz) {
  mesh::Mesh m;
  const auto node = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.coordinates.insert(m.coordinates.end(), {double(i), double(j), double(k)});
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)  // docs/theory.md 2.1 order: bottom face ccw, then top face
        m.connectivity.insert(m.connectivity.end(),
                              {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                               node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                               node(i, j + 1, k + 1)});
  const int lower = nx * ny * (nz / 2);
  m.blocks.push_back({"substrate", 0, lower});
  m.blocks.push_back({"asperity", lower, nx * ny * nz - lower});
  return m;
}

/// Sample fields at time t: displacement u = t (x, 2y, -z) m, temperature 300 + t x K,
/// stress (Voigt xx yy zz xy yz zx) = (e+1)(1+t)(1, 2, 3, 4, 5, 6) Pa, plastic_strain 0.01 e t,
/// slip (2 components, written as an XDMF "Matrix") = (t e, -t) m.
struct SampleFields {
  std::vector<double> displacement, temperature, stress, plastic_strain, slip;
  void fill(const mesh::Mesh& m, double t) {
    const int n = m.node_count(), e = m.element_count();
    displacement.resize(3 * std::size_t(n));
    temperature.resize(std::size_t(n));
    stress.resize(6 * std::size_t(e));
    plastic_strain.resize(std::size_t(e));
    slip.resize(2 * std::size_t(e));
    for (int a = 0; a < n; ++a) {
      const double* x = &m.coordinates[3 * std::size_t(a)];
      displacement[3 * a] = t * x[0];
      displacement[3 * a + 1] = 2 * t * x[1];
      displacement[3 * a + 2] = -t * x[2];
      temperature[a] = 300 + t * x[0];
    }
    for (int k = 0; k < e; ++k) {
      for (int c = 0; c < 6; ++c) stress[6 * k + c] = (k + 1) * (1 + t) * (c + 1);
      plastic_strain[k] = 0.01 * k * t;
      slip[2 * k] = t * k;
      slip[2 * k + 1] = -t;
    }
  }
  std::vector<solver::FieldView> nodal() const {
    return {{"displacement", 3, displacement, "m"}, {"temperature", 1, temperature, "K"}};
  }
  std::vector<solver::FieldView> element() const {
    return {{"stress", 6, stress, "Pa"}, {"plastic_strain", 1, plastic_strain, "1"}, {"slip", 2, slip, "m"}};
  }
};

inline const std::vector<double> sample_times = {0.0, 0.25, 0.5};

/// Writes the sample case (3 x 2 x 2 box, three steps) into `directory`. scale: the box's size in
/// metres per unit cube; 1e-9 makes a nanometre model, which the writer puts in nm (coordinates,
/// displacement and slip read x 1e9; the fields are still filled from the SI coordinates).
inline void write_sample_case(const std::string& directory, double scale = 1.0) {
  mesh::Mesh m = make_hand_box(3, 2, 2);
  for (double& x : m.coordinates) x *= scale;
  solver::ResultsWriter w(directory, m);
  SampleFields f;
  for (double t : sample_times) {
    f.fill(m, t);
    const auto nodal = f.nodal();
    const auto element = f.element();
    w.write_step(t, nodal, element);
  }
}

}  // namespace tribex::test
