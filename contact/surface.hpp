// SPDX-License-Identifier: MIT
// A contact surface: the quad faces of a side set and their nodes, with reference tributary areas.
//
// Layouts: face_nodes [face][4] global node indices, counter-clockwise seen from outside the body
// (outward normal); nodes [k] the surface's unique global nodes, sorted; node_area [k] the row sum
// of int N_I dA over the surface (A_f / 4 per node for a parallelogram face), m^2;
// face_area [face] its reference area; node_faces_offset/node_faces: faces touching surface node k (CSR);
// edge_shared [face][4]: whether edge a -> a+1 is inside the surface (shared by two faces) or on its boundary.
#pragma once

#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace tribex::contact {

struct ContactSurface {
  std::string name;
  std::vector<int> face_nodes;
  std::vector<int> face_local;  // [face][4] the same nodes as indices into `nodes`
  std::vector<int> nodes;
  std::vector<double> node_area;
  std::vector<double> face_area;  // [face] reference area, m^2
  std::vector<int> node_faces_offset;
  std::vector<int> node_faces;
  std::vector<unsigned char> edge_shared;  // [face][4] edge a -> (a+1)%4 also belongs to another face (not the boundary)
  double mean_edge = 0.0;  // mean face edge length, m

  int face_count() const { return static_cast<int>(face_nodes.size() / 4); }
  int node_count() const { return static_cast<int>(nodes.size()); }
  /// The positions of face `face`'s four nodes, X [4][3], from x [node][3].
  void face_coordinates(const double* x, int face, double X[12]) const {
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) X[3 * a + i] = x[3 * face_nodes[4 * face + a] + i];
  }
};

/// Surface from the side sets `side_sets` of `mesh` (which must exist; the caller reports a missing
/// name with its deck line).
ContactSurface make_surface(const mesh::Mesh& mesh, const std::string& name, const std::vector<std::string>& side_sets);

/// Surface from its faces: `face_nodes` [face][4] node indices into `X` ([node][3], m), counter-clockwise
/// seen from outside (the contact's own node numbering, solver/setup/contact_setup.hpp).
ContactSurface make_surface(const std::string& name, const double* X, std::vector<int> face_nodes);

}  // namespace tribex::contact
