// SPDX-License-Identifier: MIT
// The narrow phase's shortcuts (contact/node_to_face/face_bounds.hpp, closest_face.hpp):
// - the face bound never rules out a point that project_onto_quad finds over the face (points put
//   on the normal lines of warped faces, in the tolerance band included), and the box distance is
//   never above the distance to the face's closest boundary point;
// - closest_face with bounds and any seed gives the same bits as the plain scan of every candidate,
//   on a curved, warped master with points over it, beside it and below it;
// - ties (two faces at the same distance) go to the first in the candidate list, whatever the seed;
// - the boundary projection alone is project_onto_quad's answer, bit for bit, off the face.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "contact/node_to_face/closest_face.hpp"
#include "contact/node_to_face/face_bounds.hpp"

namespace tribex::contact {
namespace {

constexpr double nm = 1e-9;
constexpr double xi_a[4] = {-1, 1, 1, -1};
constexpr double eta_a[4] = {-1, -1, 1, 1};

// A unit-ish quad (edge `h`) around `origin`, its corners moved by up to `warp` x h in each direction.
void random_quad(std::mt19937& rng, double h, double warp, const double origin[3], double X[12]) {
  std::uniform_real_distribution<double> u(-warp * h, warp * h);
  for (int a = 0; a < 4; ++a) {
    X[3 * a + 0] = origin[0] + 0.5 * h * xi_a[a] + u(rng);
    X[3 * a + 1] = origin[1] + 0.5 * h * eta_a[a] + u(rng);
    X[3 * a + 2] = origin[2] + u(rng);
  }
}

// x(s, t) and the unit normal there (the face map of quad_projection.cpp).
void point_and_normal(const double X[12], double s, double t, double x[3], double n[3]) {
  double xs[3] = {0, 0, 0}, xe[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i) x[i] = 0.0;
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) {
      x[i] += 0.25 * (1 + xi_a[a] * s) * (1 + eta_a[a] * t) * X[3 * a + i];
      xs[i] += 0.25 * xi_a[a] * (1 + eta_a[a] * t) * X[3 * a + i];
      xe[i] += 0.25 * eta_a[a] * (1 + xi_a[a] * s) * X[3 * a + i];
    }
  const double c[3] = {xs[1] * xe[2] - xs[2] * xe[1], xs[2] * xe[0] - xs[0] * xe[2], xs[0] * xe[1] - xs[1] * xe[0]};
  const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  for (int i = 0; i < 3; ++i) n[i] = c[i] / len;
}

TEST(FaceBound, NeverRulesOutAPointThatProjectsInside) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> st(-1.0 - interior_tolerance, 1.0 + interior_tolerance), g(-12.0, 12.0),
      unit(-1.0, 1.0);
  const double h = 0.5 * nm, origin[3] = {120 * nm, -35 * nm, 40 * nm};
  int inside = 0, ruled_out_far = 0, far = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    double X[12];
    random_quad(rng, h, trial % 2 ? 0.3 : 0.05, origin, X);
    const FaceBound b = bound_face(X, interior_tolerance);
    // On the normal line of a point of the (slightly widened) face: usually projects inside.
    double x[3], n[3], p[3];
    point_and_normal(X, st(rng), st(rng), x, n);
    const double along = g(rng) * h;
    for (int i = 0; i < 3; ++i) p[i] = x[i] + along * n[i];
    const Projection pr = project_onto_quad(X, p);
    if (pr.interior) {
      ++inside;
      EXPECT_TRUE(b.may_project_inside(p)) << "trial " << trial;
    } else {
      EXPECT_LE(b.box_distance(p), pr.distance * (1 + 1e-12)) << "trial " << trial;
    }
    // Anywhere around it, up to 12 face sizes away.
    for (int i = 0; i < 3; ++i) p[i] = origin[i] + 12 * h * unit(rng);
    const Projection q = project_onto_quad(X, p);
    if (q.interior) {
      EXPECT_TRUE(b.may_project_inside(p)) << "trial " << trial;
    }
    EXPECT_LE(b.box_distance(p), q.distance * (1 + 1e-12)) << "trial " << trial;
    if (trial % 2 == 0 && !q.interior && std::hypot(p[0] - origin[0], p[1] - origin[1]) > 4 * h && std::abs(p[2] - origin[2]) < 2 * h) {
      ++far;
      ruled_out_far += !b.may_project_inside(p);
    }
  }
  EXPECT_GT(inside, 3000);  // the normal-line points mostly land inside: the first check is exercised
  // The bound is useful: points beside a mildly warped face (4+ sizes across, within 2 of its height)
  // are ruled out.
  ASSERT_GT(far, 200);
  EXPECT_GT(ruled_out_far, 0.95 * far) << ruled_out_far << " of " << far;
}

// project_onto_quad_boundary is project_onto_quad's fallback alone: where the Newton point is not over
// the face (every point the face bound rules out among them), the two give the same bits, which is
// what lets closest_face skip the Newton iteration for such faces.
TEST(QuadProjection, BoundaryAloneIsTheFallbackBitwise) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double h = 0.5 * nm, origin[3] = {120 * nm, -35 * nm, 40 * nm};
  int outside = 0, ruled_out = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    double X[12], p[3];
    random_quad(rng, h, trial % 2 ? 0.3 : 0.05, origin, X);
    for (int i = 0; i < 3; ++i) p[i] = origin[i] + 6 * h * unit(rng);
    const Projection full = project_onto_quad(X, p);
    if (full.interior) continue;
    ++outside;
    ruled_out += !bound_face(X, interior_tolerance).may_project_inside(p);
    const Projection edge = project_onto_quad_boundary(X, p);
    EXPECT_FALSE(edge.interior);
    EXPECT_EQ(edge.xi, full.xi) << "trial " << trial;
    EXPECT_EQ(edge.eta, full.eta) << "trial " << trial;
    EXPECT_EQ(edge.gap, full.gap) << "trial " << trial;
    EXPECT_EQ(edge.distance, full.distance) << "trial " << trial;
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(edge.point[i], full.point[i]) << "trial " << trial;
      EXPECT_EQ(edge.normal[i], full.normal[i]) << "trial " << trial;
    }
    for (int a = 0; a < 4; ++a) EXPECT_EQ(edge.shape[a], full.shape[a]) << "trial " << trial;
  }
  EXPECT_GT(outside, 2000);
  EXPECT_GT(ruled_out, 1000);  // the case closest_face takes the shortcut in is exercised
}

// A curved, warped master: n x n faces of edge h on a bowl (a sphere cap of radius R; outward normal
// about +z), its nodes jittered.
ContactSurface bumpy_master(std::mt19937& rng, int n, double h, double R, std::vector<double>& x) {
  std::uniform_real_distribution<double> jitter(-0.08 * h, 0.08 * h);
  x.clear();
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double X = (i - 0.5 * n) * h, Y = (j - 0.5 * n) * h;
      x.insert(x.end(), {X + jitter(rng), Y + jitter(rng), R - std::sqrt(R * R - X * X - Y * Y) + jitter(rng)});
    }
  std::vector<int> faces;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      faces.insert(faces.end(), {a, a + 1, a + n + 2, a + n + 1});  // counter-clockwise seen from +z
    }
  return make_surface("master", x.data(), faces);
}

void expect_same(const BestFace& a, const BestFace& b, int point) {
  ASSERT_EQ(a.face, b.face) << "point " << point;
  EXPECT_EQ(a.usable, b.usable) << "point " << point;
  EXPECT_EQ(a.proj.interior, b.proj.interior) << "point " << point;
  EXPECT_EQ(a.proj.gap, b.proj.gap) << "point " << point;  // bitwise: the same projection
  EXPECT_EQ(a.proj.distance, b.proj.distance) << "point " << point;
  for (int i = 0; i < 3; ++i) EXPECT_EQ(a.proj.normal[i], b.proj.normal[i]) << "point " << point;
}

TEST(ClosestFace, BoundsAndSeedsGiveThePlainScansAnswer) {
  std::mt19937 rng(11);
  const int n = 16;
  const double h = 0.5 * nm, R = 20 * nm, half = 0.5 * n * h;
  std::vector<double> x;
  const ContactSurface master = bumpy_master(rng, n, h, R, x);
  std::vector<int> all(master.face_count());
  for (int f = 0; f < master.face_count(); ++f) all[f] = f;
  FaceBounds bounds;
  bounds.resize(master.face_count());
  bounds.next_step();
  std::uniform_real_distribution<double> lateral(-1.4 * half, 1.4 * half), height(-1.5 * nm, 4 * nm);
  std::uniform_int_distribution<int> any_face(0, master.face_count() - 1);
  int interior = 0, kink = 0, beside = 0, changed_seed = 0;
  for (int point = 0; point < 1500; ++point) {
    const double p[3] = {lateral(rng), lateral(rng), height(rng)};
    // The candidate list in a random order, half of the faces (a seed may then be missing from it).
    std::vector<int> list = all;
    std::shuffle(list.begin(), list.end(), rng);
    list.resize(list.size() / 2);
    const int count = static_cast<int>(list.size());
    const BestFace plain = closest_face(x.data(), master, list.data(), count, p);
    interior += plain.proj.interior;
    kink += !plain.proj.interior && plain.usable;
    beside += !plain.proj.interior && !plain.usable;
    for (int seed : {-1, any_face(rng), list[count / 3], plain.face}) {
      const BestFace fast = closest_face(x.data(), master, list.data(), count, p, -1, &bounds, seed);
      expect_same(plain, fast, point);
      changed_seed += seed != plain.face;
    }
    // A hint the node has left: the scan starts from it.
    const int hint = any_face(rng);
    const BestFace hinted = closest_face(x.data(), master, list.data(), count, p, hint);
    expect_same(hinted, closest_face(x.data(), master, list.data(), count, p, hint, &bounds, -1), point);
  }
  // All three kinds of answer are exercised (interior 282, kink 442, beside 776 with these seeds).
  EXPECT_GT(interior, 200);
  EXPECT_GT(kink, 200);
  EXPECT_GT(beside, 400);
  EXPECT_GT(changed_seed, 3000);
}

TEST(ClosestFace, TiesGoToTheFirstCandidateWhateverTheSeed) {
  // Two copies of one face (the same four nodes): every projection ties bit for bit.
  const double h = 0.5 * nm;
  const std::vector<double> x = {0, 0, 0, h, 0, 0, h, h, 0, 0, h, 0};
  const ContactSurface master = make_surface("twice", x.data(), {0, 1, 2, 3, 0, 1, 2, 3});
  FaceBounds bounds;
  bounds.resize(2);
  bounds.next_step();
  for (const double px : {0.5 * h, 3 * h}) {  // over the face, and beside it
    const double p[3] = {px, 0.5 * h, 0.2 * h};
    for (const std::vector<int>& list : {std::vector<int>{0, 1}, std::vector<int>{1, 0}})
      for (int seed : {-1, 0, 1}) {
        const BestFace best = closest_face(x.data(), master, list.data(), 2, p, -1, &bounds, seed);
        EXPECT_EQ(best.face, list[0]) << "p.x " << px << " seed " << seed;
      }
  }
}

}  // namespace
}  // namespace tribex::contact
