// SPDX-License-Identifier: MIT
#include "contact/node_to_face/closest_face.hpp"

#include <cmath>

namespace tribex::contact {
namespace {

// A node that no candidate face projects in its interior, whose closest point lies on an edge or a
// vertex inside the master surface (not on its boundary), sits in the wedge in front of a ridge or
// behind a valley of the faceted surface: a soft master folds into a valley under each of the slave's
// point loads, and the loaded node sits below it (tests/contact/kink_test.cpp). Its gap is then the signed distance to that point, along the line to it
// (the face normal otherwise), so the gap and the force direction stay continuous as the node
// crosses from a face's region into the wedge. Dropping such a node, as the projection alone would,
// removes a penalty force with its stored energy 1/2 k g^2 and adds it back on re-entry: on a 2 nm
// coating that made the contact inject up to 10 % of the energy (issue 22, contact/README.md).
bool at_kink(const ContactSurface& master, int face, const double* p, Projection& proj) {
  const bool on_edge[4] = {proj.eta <= -1.0, proj.xi >= 1.0, proj.eta >= 1.0, proj.xi <= -1.0};
  for (int e = 0; e < 4; ++e)
    if (on_edge[e] && !master.edge_shared[4 * face + e]) return false;  // the surface's own boundary
  if (!(proj.distance > 0.0)) return false;
  const double sign = proj.gap < 0.0 ? -1.0 : 1.0;
  for (int i = 0; i < 3; ++i) proj.normal[i] = sign * (p[i] - proj.point[i]) / proj.distance;
  proj.gap = sign * proj.distance;
  return true;
}

}  // namespace

BestFace closest_face(const double* x, const ContactSurface& master, const int* faces, int count, const double* p,
                      int hint) {
  if (hint >= 0) {
    double X[12];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) X[3 * a + i] = x[3 * master.face_nodes[4 * hint + a] + i];
    const Projection pr = project_onto_quad(X, p);
    if (pr.interior) return {hint, pr, true};
  }
  BestFace best;
  double best_key = INFINITY;
  bool best_interior = false;
  for (int c = 0; c < count; ++c) {
    const int f = faces[c];
    double X[12];
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) X[3 * a + i] = x[3 * master.face_nodes[4 * f + a] + i];
    const Projection pr = project_onto_quad(X, p);
    const double key = pr.interior ? std::abs(pr.gap) : pr.distance;
    if ((pr.interior && !best_interior) || (pr.interior == best_interior && key < best_key)) {
      best = {f, pr, pr.interior};
      best_key = key;
      best_interior = pr.interior;
    }
  }
  if (best.face >= 0 && !best.usable) best.usable = at_kink(master, best.face, p, best.proj);
  return best;
}


}  // namespace tribex::contact
