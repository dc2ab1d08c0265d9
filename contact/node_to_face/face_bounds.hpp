// SPDX-License-Identifier: MIT
// Cheap, conservative bounds of a master face for the narrow phase (closest_face.cpp): its node box
// and a test that a point cannot project into its interior. They let closest_face skip the Newton
// projection of candidates that cannot change its answer: a slave node beside the master (over no
// face, case (b) of inputs/examples/afm_sliding: the track's nodes around the tip) otherwise projects
// on each of its ~250 candidates every step.
#pragma once

#include <vector>

#include "contact/surface.hpp"

namespace tribex::contact {

struct FaceBound {
  double lo[3], hi[3];  // box of the four nodes, m
  double centre[3];     // mean of the four nodes, m
  double normal[3];     // unit normal at the centre (xi = eta = 0)
  double reach;         // bound on |x(xi, eta) - centre| over the accepted parametric square, m
  double spread;        // bound on the sine of the angle between the normal anywhere on that square and `normal`
  bool tested;          // false: a face too warped for the bound (spread undefined); never ruled out

  /// False only if no point of the face with |xi|, |eta| <= 1 + tolerance has p on its normal line, so
  /// project_onto_quad(face, p, tolerance) cannot report `interior` (proof in face_bounds.cpp).
  bool may_project_inside(const double* p) const;
  /// Distance from p to the node box, m: a lower bound on the distance to any point of the face.
  double box_distance(const double* p) const;
};

/// `X` the four nodes [4][3] (counter-clockwise from outside); `tolerance` as project_onto_quad's.
FaceBound bound_face(const double X[12], double tolerance);

/// Bounds of a surface's faces at the current positions, computed on first use in each step: a pass
/// touches only the faces its slave nodes' candidate lists name (storage sized once: no allocation
/// in the step loop).
class FaceBounds {
 public:
  void resize(int face_count);
  /// Forget the bounds of the previous positions (call once per step before use).
  void next_step();
  /// The bound of `face` of `surface` at positions `x` for project_onto_quad's interior_tolerance.
  const FaceBound& of(const double* x, const ContactSurface& surface, int face);

 private:
  std::vector<FaceBound> bound_;
  std::vector<unsigned> stamp_;  // [face] epoch_ of the step its bound was computed in
  unsigned epoch_ = 1;
};

}  // namespace tribex::contact
