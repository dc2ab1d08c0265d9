// SPDX-License-Identifier: MIT
// Segment-to-segment (mortar) contact: polygon clipping, the overlap integration of one face pair,
// and the consistent nodal loads of a uniform penetration on non-matching flat meshes.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contact/contact_manager.hpp"
#include "contact/geometry/polygon_clip.hpp"
#include "contact/mortar/segment_quadrature.hpp"
#include "mesh/box.hpp"

namespace tribex::contact {
namespace {

constexpr double nm = 1e-9;

Polygon2 square(double cx, double cy, double half, double angle) {
  Polygon2 p;
  p.count = 4;
  const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
  for (int a = 0; a < 4; ++a) {
    p.x[a] = cx + half * (std::cos(angle) * sx[a] - std::sin(angle) * sy[a]);
    p.y[a] = cy + half * (std::sin(angle) * sx[a] + std::cos(angle) * sy[a]);
  }
  return p;
}

TEST(PolygonClip, OverlapAreasOfSquares) {
  const Polygon2 unit = square(0, 0, 1, 0);
  EXPECT_NEAR(signed_area(unit), 4.0, 1e-15);
  // Shifted square: overlap 1.5 x 1 of two 2 x 2 squares shifted by (0.5, 1).
  EXPECT_NEAR(signed_area(clip_convex(square(0.5, 1.0, 1, 0), unit)), 1.5, 1e-15);
  // Coincident squares: the whole square (matching meshes: edges on edges).
  EXPECT_NEAR(signed_area(clip_convex(unit, unit)), 4.0, 1e-15);
  // The same square rotated by 45 degrees: a regular octagon of inradius 1, area 8 (sqrt 2 - 1).
  EXPECT_NEAR(signed_area(clip_convex(square(0, 0, 1, M_PI / 4), unit)), 8.0 * (std::sqrt(2.0) - 1.0), 1e-14);
  // Disjoint and edge-touching squares: no area.
  EXPECT_EQ(clip_convex(square(3.0, 0.0, 1, 0), unit).count, 0);
  EXPECT_NEAR(std::abs(signed_area(clip_convex(square(2.0, 0.0, 1, 0), unit))), 0.0, 1e-15);
  // A small square inside: itself.
  EXPECT_NEAR(signed_area(clip_convex(square(0.2, -0.1, 0.3, 0.3), unit)), 0.36, 1e-15);
  // An edge almost on a clip edge (coincident free edges of two meshes, moved by round-off): one
  // end just inside the tolerance 2e-12, the other just beyond. The crossing must stay on the
  // edge: an extrapolated one (t = si / (si - sj) = -9.5 here) added a sliver of 4e-4 of a face.
  Polygon2 near;
  near.count = 4;
  const double px[4] = {0.0, 1.0 + 1.9e-12, 1.0 + 2.1e-12, 0.0}, py[4] = {0.5, 0.5, 2.0, 2.0};
  for (int a = 0; a < 4; ++a) {
    near.x[a] = px[a];
    near.y[a] = py[a];
  }
  EXPECT_NEAR(signed_area(clip_convex(near, unit)), 0.5, 1e-11);
}

// Face corners [4][3] of a flat quad in the plane z = z, counter-clockwise seen from +z when
// `up`, else clockwise (outward normal -z).
void flat_face(const double (&xy)[4][2], double z, bool up, double X[12]) {
  for (int a = 0; a < 4; ++a) {
    const int b = up ? a : (a == 0 ? 0 : 4 - a);
    X[3 * a] = xy[b][0];
    X[3 * a + 1] = xy[b][1];
    X[3 * a + 2] = z;
  }
}

// One slave face (a parallelogram, outward normal -z) over the four master faces of a 2 x 2
// patch (normal +z) that covers it, gap g0 everywhere: the integration areas sum to the slave
// face's area, shape functions are a partition of unity at every point, int N_a dA = A/4 (exact
// for a parallelogram), sum_a M_ab = sum_k D_kb, and the gap is g0 at every point.
TEST(SegmentQuadrature, AreasPartitionOfUnityAndGap) {
  const double g0 = 0.01;
  const double slave_xy[4][2] = {{0.3, 0.2}, {1.4, 0.35}, {1.6, 1.5}, {0.5, 1.35}};  // parallelogram
  double X[12];
  flat_face(slave_xy, 0.0, false, X);
  const SlaveFacePlane plane = slave_face_plane(X);
  EXPECT_NEAR(plane.normal[2], -1.0, 1e-15);
  const double area = std::abs(signed_area(plane.polygon));
  double total = 0.0, intN[4] = {0, 0, 0, 0}, rowM[4] = {0, 0, 0, 0}, rowD[4] = {0, 0, 0, 0};
  SegmentQuadrature q;
  int segments = 0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const double x0 = i, y0 = j;
      const double master_xy[4][2] = {{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}};
      double Y[12];
      flat_face(master_xy, -g0, true, Y);
      if (!integrate_segment(plane, Y, q)) continue;
      ++segments;
      double seg = 0.0;
      for (int p = 0; p < q.count; ++p) {
        seg += q.weight[p];
        double sumN = 0.0, sumPhi = 0.0;
        for (int a = 0; a < 4; ++a) {
          sumN += q.slave_shape[p][a];
          sumPhi += q.master_shape[p][a];
          intN[a] += q.weight[p] * q.slave_shape[p][a];
          for (int b = 0; b < 4; ++b) {
            rowM[b] += q.weight[p] * q.slave_shape[p][a] * q.slave_shape[p][b];
            rowD[b] += q.weight[p] * q.master_shape[p][a] * q.slave_shape[p][b];
          }
        }
        EXPECT_NEAR(sumN, 1.0, 1e-14);
        EXPECT_NEAR(sumPhi, 1.0, 1e-14);
        EXPECT_NEAR(q.gap[p], g0, 1e-15);  // the master g0 below the slave (its outward side): apart
      }
      EXPECT_NEAR(seg, q.area, 1e-15);
      total += seg;
    }
  EXPECT_EQ(segments, 4);
  EXPECT_NEAR(total / area, 1.0, 1e-14);
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(intN[a] / (area / 4), 1.0, 1e-13) << a;
    EXPECT_NEAR(rowM[a] / rowD[a], 1.0, 1e-13) << a;
  }
}

TEST(SegmentQuadrature, BackFacingMasterIsSkipped) {
  const double xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  double X[12], Y[12];
  flat_face(xy, 0.0, false, X);
  flat_face(xy, -0.1, false, Y);  // same orientation as the slave: faces away
  SegmentQuadrature q;
  EXPECT_FALSE(integrate_segment(slave_face_plane(X), Y, q));
}

// Two slabs with non-matching grids; the upper (slave) one lowered by `overlap` into the lower.
struct Flats {
  mesh::Mesh mesh;
  std::vector<double> mass;
  std::unique_ptr<ContactManager> manager;
};

Flats flats(double overlap, double angle, int upper_n, int lower_n, double lower_half, Enforcement e) {
  mesh::BoxSpec lower;
  lower.name = "lower";
  lower.origin = {-lower_half, -lower_half, -2 * nm};
  lower.size = {2 * lower_half, 2 * lower_half, 2 * nm};
  lower.intervals = {lower_n, lower_n, 1};
  mesh::BoxSpec upper;
  upper.name = "upper";
  upper.origin = {-5 * nm, -5 * nm, -overlap};
  upper.size = {10 * nm, 10 * nm, 2 * nm};
  upper.intervals = {upper_n, upper_n, 1};
  Flats f;
  f.mesh = mesh::generate_box(lower);
  mesh::Mesh up = mesh::generate_box(upper);
  for (std::size_t n = 0; n < up.coordinates.size() / 3; ++n) {  // rotate the upper slab about z
    const double x = up.coordinates[3 * n], y = up.coordinates[3 * n + 1];
    up.coordinates[3 * n] = std::cos(angle) * x - std::sin(angle) * y;
    up.coordinates[3 * n + 1] = std::sin(angle) * x + std::cos(angle) * y;
  }
  mesh::append(f.mesh, up);
  f.mass.assign(f.mesh.node_count(), 1e-24);
  InteractionSettings s;
  s.slave = 0;
  s.master = 1;
  s.enforcement = e;
  std::vector<ContactSurface> surfaces = {make_surface(f.mesh, "slave", {"upper_zmin"}),
                                          make_surface(f.mesh, "master", {"lower_zmax"})};
  f.manager = std::make_unique<ContactManager>(std::move(surfaces), std::vector<InteractionSettings>{s}, f.mass, 1e-15,
                                               f.mesh.node_count());
  return f;
}

// Uniform penetration on non-matching flat meshes (3 x 3 slave faces on 4 x 4 master faces,
// same 10 x 10 nm extent): every slave node carries p int N_i dA and every master node
// p int Phi_k dA (their tributary areas), to 1e-12 relative; total force p A.
TEST(MortarContact, UniformPenetrationGivesConsistentNodalLoads) {
  const double overlap = 0.01 * nm;
  Flats f = flats(overlap, 0.0, 3, 4, 5 * nm, Enforcement::mortar);
  std::vector<double> force(f.mesh.coordinates.size(), 0.0);
  const ContactTotals t = f.manager->compute_forces(f.mesh.coordinates.data(), nullptr, force.data());
  const double A = 100 * nm * nm;
  const double p = t.compressive_force / A;
  EXPECT_GT(p, 0.0);
  // The penalty law: p = k_A x overlap, k_A = m_A / dt^2 (scale 1), m_A = a b / (a + b).
  const auto& slave = f.manager->surfaces()[0];
  const auto& master = f.manager->surfaces()[1];
  const double k_A = mortar_penalty_per_area(slave, master, f.mass, 1.0, 1e-15);
  EXPECT_NEAR(p / (k_A * overlap), 1.0, 1e-12);
  for (int k = 0; k < slave.node_count(); ++k) {
    const int n = slave.nodes[k];
    EXPECT_NEAR(force[3 * n + 2] / (p * slave.node_area[k]), 1.0, 1e-12) << "slave node " << n;
    EXPECT_NEAR(force[3 * n] / (p * slave.node_area[k]), 0.0, 1e-12);
    EXPECT_NEAR(force[3 * n + 1] / (p * slave.node_area[k]), 0.0, 1e-12);
  }
  for (int k = 0; k < master.node_count(); ++k) {
    const int n = master.nodes[k];
    EXPECT_NEAR(force[3 * n + 2] / (-p * master.node_area[k]), 1.0, 1e-12) << "master node " << n;
  }
  EXPECT_NEAR(t.area / A, 1.0, 1e-12);
  EXPECT_EQ(t.nodes, slave.node_count());
}

// A mass-scaled run (ContactManager::set_unscaled_penalty_reference, docs/theory.md 1.4.1): the mortar
// k_A keeps the unscaled masses' and step's value, s m_A,0 / dt_0^2, bounded by s m_A / dt^2 on the run's
// masses and step (k_A dt^2 / m_A <= s; in a run the contact-node raise keeps the bound from binding).
TEST(MortarContact, MassScaledRunKeepsTheUnscaledPenaltyUpToTheBound) {
  const double overlap = 0.01 * nm;
  Flats f = flats(overlap, 0.0, 3, 4, 5 * nm, Enforcement::mortar);
  const auto pressure = [&](const std::vector<double>& unscaled_mass, double unscaled_dt) {
    // The manager's run step is 1e-15 s on masses f.mass.
    f.manager->set_unscaled_penalty_reference(unscaled_mass, unscaled_dt);
    std::vector<double> force(f.mesh.coordinates.size(), 0.0);
    return f.manager->compute_forces(f.mesh.coordinates.data(), nullptr, force.data()).compressive_force / (100 * nm * nm);
  };
  const auto& slave = f.manager->surfaces()[0];
  const auto& master = f.manager->surfaces()[1];
  const double k_run = mortar_penalty_per_area(slave, master, f.mass, 1.0, 1e-15);
  // Masses raised by 1.69 with the step (the raise m >= (dt/dt_0)^2 m_0): k_A,0 = k_A(run), kept exactly.
  std::vector<double> lighter = f.mass;
  for (double& m : lighter) m /= 1.69;
  EXPECT_NEAR(pressure(lighter, 1e-15 / 1.3) / (k_run * overlap), 1.0, 1e-12);
  // Masses raised by 2.56 (more than the step asks): k_A,0 = (1.69 / 2.56) k_A(run), the unscaled value.
  for (double& m : lighter) m *= 1.69 / 2.56;
  EXPECT_NEAR(pressure(lighter, 1e-15 / 1.3) / (1.69 / 2.56 * k_run * overlap), 1.0, 1e-12);
  // The step grew by 2, the masses did not: k_A,0 would be 4 k_A(run); the bound holds it at k_A(run).
  EXPECT_NEAR(pressure(f.mass, 1e-15 / 2.0) / (k_run * overlap), 1.0, 1e-12);
}

// Node-to-face on the same pair, for contrast: the master loads are not the consistent ones.
TEST(MortarContact, NodeToFaceMasterLoadsAreNotConsistent) {
  Flats f = flats(0.01 * nm, 0.0, 3, 4, 5 * nm, Enforcement::node_to_face);
  std::vector<double> force(f.mesh.coordinates.size(), 0.0);
  const ContactTotals t = f.manager->compute_forces(f.mesh.coordinates.data(), nullptr, force.data());
  const double p = t.compressive_force / (100 * nm * nm);
  const auto& master = f.manager->surfaces()[1];
  double worst = 0.0;
  for (int k = 0; k < master.node_count(); ++k)
    worst = std::max(worst, std::abs(force[3 * master.nodes[k] + 2] / (-p * master.node_area[k]) - 1.0));
  EXPECT_GT(worst, 0.05);
}

// A rotated slave slab (20 degrees) on a larger master: slave loads consistent to 1e-12, total
// momentum conserved to round-off, the master receiving exactly the slave's total.
TEST(MortarContact, RotatedNonMatchingMeshConservesMomentum) {
  Flats f = flats(0.01 * nm, 20.0 * M_PI / 180.0, 4, 7, 8 * nm, Enforcement::mortar);
  std::vector<double> force(f.mesh.coordinates.size(), 0.0);
  const ContactTotals t = f.manager->compute_forces(f.mesh.coordinates.data(), nullptr, force.data());
  const double p = t.compressive_force / (100 * nm * nm);
  const auto& slave = f.manager->surfaces()[0];
  for (int k = 0; k < slave.node_count(); ++k)
    EXPECT_NEAR(force[3 * slave.nodes[k] + 2] / (p * slave.node_area[k]), 1.0, 1e-12);
  double sum[3] = {0, 0, 0};
  for (std::size_t n = 0; n < force.size() / 3; ++n)
    for (int i = 0; i < 3; ++i) sum[i] += force[3 * n + i];
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(sum[i] / t.compressive_force, 0.0, 1e-14) << i;
}

// The forces are a continuous function of the positions: perturbations of size eps change them
// by O(k eps), from 1e-6 of the overlap down to round-off (a discontinuity, e.g. a segment that
// appears or vanishes with a clipping decision, would show as a jump independent of eps).
TEST(MortarContact, ForcesAreContinuousInThePositions) {
  const double overlap = 0.01 * nm;
  Flats f = flats(overlap, 0.0, 3, 4, 5 * nm, Enforcement::mortar);
  std::vector<double> f0(f.mesh.coordinates.size(), 0.0);
  const ContactTotals t = f.manager->compute_forces(f.mesh.coordinates.data(), nullptr, f0.data());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double eps : {1e-6, 1e-8, 1e-10, 1e-12}) {
    std::vector<double> x = f.mesh.coordinates, f1(x.size(), 0.0);
    for (double& c : x) c += eps * overlap * u(rng);
    f.manager->compute_forces(x.data(), nullptr, f1.data());
    double change = 0.0;
    for (std::size_t k = 0; k < f1.size(); ++k) change = std::max(change, std::abs(f1[k] - f0[k]));
    std::printf("eps %.0e: largest nodal force change / total %.3e\n", eps, change / t.compressive_force);
    EXPECT_LT(change / t.compressive_force, 10 * eps + 1e-14) << eps;
  }
}

}  // namespace
}  // namespace tribex::contact
