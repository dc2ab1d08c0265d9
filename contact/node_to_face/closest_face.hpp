// SPDX-License-Identifier: MIT
// Narrow phase of node-to-face contact (step 2 of a pass, contact_manager.hpp): the master face a
// slave node is over, among its broad-phase candidates.
#pragma once

#include "contact/geometry/quad_projection.hpp"
#include "contact/surface.hpp"

namespace tribex::contact {

struct BestFace {
  int face = -1;
  Projection proj;
  bool usable = false;  // proj.interior, or the closest point is a kink of the master (see closest_face.cpp)
};

/// Among the candidate faces of the node at p, prefer faces over which it projects (interior),
/// then the smallest |gap|; fall back to the nearest edge/vertex point inside the master (a kink).
/// `hint` (the node's face of the previous step, or -1) is tried first and kept when the node still
/// projects over it (docs/theory.md 5.1: track the current face).
BestFace closest_face(const double* x, const ContactSurface& master, const int* faces, int count, const double* p,
                      int hint = -1);

}  // namespace tribex::contact
