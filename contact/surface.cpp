// SPDX-License-Identifier: MIT
#include "contact/surface.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tribex::contact {

ContactSurface make_surface(const mesh::Mesh& mesh, const std::string& name, const std::vector<std::string>& side_sets) {
  std::vector<int> face_nodes;
  for (const auto& set : side_sets)
    for (const auto& side : mesh.side_sets.at(set)) {
      const auto n = mesh.side_nodes(side);
      face_nodes.insert(face_nodes.end(), n.begin(), n.end());
    }
  return make_surface(name, mesh.coordinates.data(), std::move(face_nodes));
}

ContactSurface make_surface(const std::string& name, const double* X, std::vector<int> face_nodes) {
  ContactSurface s;
  s.name = name;
  s.face_nodes = std::move(face_nodes);
  s.nodes = s.face_nodes;
  std::sort(s.nodes.begin(), s.nodes.end());
  s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
  auto local = [&](int global) {
    return static_cast<int>(std::lower_bound(s.nodes.begin(), s.nodes.end(), global) - s.nodes.begin());
  };
  s.face_local.resize(s.face_nodes.size());
  for (std::size_t k = 0; k < s.face_nodes.size(); ++k) s.face_local[k] = local(s.face_nodes[k]);
  s.node_area.assign(s.nodes.size(), 0.0);
  s.face_area.assign(static_cast<std::size_t>(s.face_count()), 0.0);
  std::vector<int> count(s.nodes.size() + 1, 0);
  double edge_sum = 0.0;
  for (int f = 0; f < s.face_count(); ++f) {
    const int* n = &s.face_nodes[4 * f];
    // Row-sum lumping of int N_I dA with 2x2 Gauss (exact for the bilinear map's area density).
    const double g = 0.57735026918962576451;
    for (int q = 0; q < 4; ++q) {
      const double xi = (q == 1 || q == 2) ? g : -g, eta = q >= 2 ? g : -g;
      double xs[3] = {}, xe[3] = {};
      const double sa[4] = {-1, 1, 1, -1}, ta[4] = {-1, -1, 1, 1};
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i) {
          xs[i] += 0.25 * sa[a] * (1 + ta[a] * eta) * X[3 * n[a] + i];
          xe[i] += 0.25 * ta[a] * (1 + sa[a] * xi) * X[3 * n[a] + i];
        }
      const double c[3] = {xs[1] * xe[2] - xs[2] * xe[1], xs[2] * xe[0] - xs[0] * xe[2], xs[0] * xe[1] - xs[1] * xe[0]};
      const double dA = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      for (int a = 0; a < 4; ++a) s.node_area[local(n[a])] += 0.25 * (1 + sa[a] * xi) * (1 + ta[a] * eta) * dA;
      s.face_area[static_cast<std::size_t>(f)] += dA;
    }
    for (int a = 0; a < 4; ++a) {
      ++count[local(n[a]) + 1];
      double e2 = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double d = X[3 * n[(a + 1) % 4] + i] - X[3 * n[a] + i];
        e2 += d * d;
      }
      edge_sum += std::sqrt(e2);
    }
  }
  s.mean_edge = s.face_count() ? edge_sum / (4.0 * s.face_count()) : 0.0;
  for (std::size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
  s.node_faces_offset = count;
  s.node_faces.assign(static_cast<std::size_t>(count.back()), 0);
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (int f = 0; f < s.face_count(); ++f)
    for (int a = 0; a < 4; ++a) s.node_faces[fill[local(s.face_nodes[4 * f + a])]++] = f;
  s.edge_shared.assign(s.face_nodes.size(), 0);
  for (int f = 0; f < s.face_count(); ++f)
    for (int a = 0; a < 4; ++a) {
      const int from = s.face_local[4 * f + a], to = s.face_nodes[4 * f + (a + 1) % 4];
      for (int c = s.node_faces_offset[from]; c < s.node_faces_offset[from + 1]; ++c) {
        const int g = s.node_faces[c];
        const int* gn = &s.face_nodes[4 * g];
        if (g != f && std::find(gn, gn + 4, to) != gn + 4) s.edge_shared[4 * f + a] = 1;
      }
    }
  return s;
}

}  // namespace tribex::contact
