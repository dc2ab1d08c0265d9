// SPDX-License-Identifier: MIT
// Narrow phase of node-to-face contact (step 2 of a pass, contact_manager.hpp): the master face a
// slave node is over, among its broad-phase candidates.
#pragma once

#include "contact/geometry/quad_projection.hpp"
#include "contact/node_to_face/face_bounds.hpp"
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
///
/// Otherwise the answer is the first candidate (in list order) of the best class and smallest key.
/// With `bounds` (the master's FaceBounds of this step) the same answer costs less: `seed` (a face
/// likely to be near, e.g. the node's answer of the previous step; ignored unless in the list) is
/// projected first, and a candidate is skipped when its bounds show it can neither project inside
/// nor come closer than the best so far (face_bounds.hpp). The order of projection then differs
/// from the list's, so ties are broken by list position explicitly: the result is the same bits.
BestFace closest_face(const double* x, const ContactSurface& master, const int* faces, int count, const double* p,
                      int hint = -1, FaceBounds* bounds = nullptr, int seed = -1);

}  // namespace tribex::contact
