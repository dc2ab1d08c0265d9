// SPDX-License-Identifier: MIT
#include "contact/node_to_face/closest_face.hpp"

#include <algorithm>
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

Projection project(const double* x, const ContactSurface& master, int face, const double* p) {
  double X[12];
  master.face_coordinates(x, face, X);
  return project_onto_quad(X, p);
}

// project(), with the Newton iteration skipped where the face's bound proves that the node cannot
// project inside it: project_onto_quad would then return its boundary fallback, computed here alone
// (the same bits). Case (b) of inputs/examples/afm_sliding: of the track nodes' projections beside
// the tip, 99 % are of faces near enough to be the nearest but provably not over them.
Projection project(const double* x, const ContactSurface& master, int face, const double* p, const FaceBound& bound) {
  double X[12];
  master.face_coordinates(x, face, X);
  return bound.may_project_inside(p) ? project_onto_quad(X, p) : project_onto_quad_boundary(X, p);
}

double key_of(const Projection& pr) { return pr.interior ? std::abs(pr.gap) : pr.distance; }

// Every candidate in list order; the first of the best class and smallest key wins.
BestFace scan(const double* x, const ContactSurface& master, const int* faces, int count, const double* p) {
  BestFace best;
  double best_key = INFINITY;
  bool best_interior = false;
  for (int c = 0; c < count; ++c) {
    const Projection pr = project(x, master, faces[c], p);
    const double key = key_of(pr);
    if ((pr.interior && !best_interior) || (pr.interior == best_interior && key < best_key)) {
      best = {faces[c], pr, pr.interior};
      best_key = key;
      best_interior = pr.interior;
    }
  }
  return best;
}

// scan's answer, projecting fewer candidates (closest_face.hpp). False when a key is NaN (a
// degenerate face): the order of projection could then matter, and the caller scans.
bool pruned_scan(const double* x, const ContactSurface& master, const int* faces, int count, const double* p,
                 FaceBounds& bounds, int seed, BestFace& best) {
  int best_pos = -1;  // list position of `best` (-1: none yet)
  double best_key = INFINITY;
  const auto consider = [&](int c, const Projection& pr) {
    const double key = key_of(pr);
    if (std::isnan(key)) return false;
    bool better;
    if (best_pos < 0) better = true;
    else if (pr.interior != best.usable) better = pr.interior;
    else if (key != best_key) better = key < best_key;
    else better = c < best_pos;
    if (better) {
      best = {faces[c], pr, pr.interior};
      best_key = key;
      best_pos = c;
    }
    return true;
  };
  const int seed_pos = seed < 0 ? -1 : static_cast<int>(std::find(faces, faces + count, seed) - faces);
  if (seed_pos >= 0 && seed_pos < count && !consider(seed_pos, project(x, master, seed, p, bounds.of(x, master, seed))))
    return false;
  for (int c = 0; c < count; ++c) {
    if (c == seed_pos) continue;
    const FaceBound& b = bounds.of(x, master, faces[c]);
    if (best_pos >= 0) {
      // Not over the face, the candidate can win only as the nearest of the non-interior ones, with a
      // key of at least its box distance (the slack covers round-off). The box test is the cheaper.
      const bool too_far = best.usable || b.box_distance(p) > best_key + 1e-9 * (best_key + b.reach);
      if (too_far && !b.may_project_inside(p)) continue;
    }
    if (!consider(c, project(x, master, faces[c], p, b))) return false;
  }
  return true;
}

}  // namespace

BestFace closest_face(const double* x, const ContactSurface& master, const int* faces, int count, const double* p,
                      int hint, FaceBounds* bounds, int seed) {
  if (hint >= 0) {
    const Projection pr = project(x, master, hint, p);
    if (pr.interior) return {hint, pr, true};
    seed = hint;  // the node has just left it: a near face
  }
  BestFace best;
  if (!bounds || !pruned_scan(x, master, faces, count, p, *bounds, seed, best))
    best = scan(x, master, faces, count, p);
  if (best.face >= 0 && !best.usable) best.usable = at_kink(master, best.face, p, best.proj);
  return best;
}

}  // namespace tribex::contact
