// SPDX-License-Identifier: MIT
// Adhesion integrated at face quadrature points (enforcement = mortar) against nodal tributary
// areas (node to face), on the rigid-sphere-above-rigid-flat handle of docs/theory.md 6.5 with COARSE
// meshes: element sizes comparable to the range of the law's variation on the sphere.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/contact_manager.hpp"
#include "mesh/asperity.hpp"
#include "tests/support/asperity_outline.hpp"
#include "support.hpp"

namespace tribex::contact {
namespace {

using test::nm;
constexpr double W = 0.05, z0 = 0.2e-9;

struct Case {
  mesh::Mesh mesh;
  double fe_surface_force = 0.0;  // the applied law integrated over the FE (faceted) tip surface
};

Case make_case(double element_size, double D) {
  mesh::AsperitySpec a = tribex::test::asperity_outline(27 * nm, 30 * nm, 21 * nm, 32 * nm, 2 * nm, element_size);
  a.gap = D;
  a.fine_half_width = 14 * nm;  // uniform elements over the interacting region (g_c reached at r = 13.7 nm)
  a.fine_depth = element_size;
  a.grading_ratio = 1.2;
  Case c;
  c.mesh = mesh::generate_asperity(a);
  return c;
}

// The applied law integrated over the FE tip surface itself (bilinear faces, their true area, the
// separation z - z_flat of each point from the flat's plane z = 0), midpoint rule on 32 x 32
// parametric cells per face: the reference that isolates the integration rule from the faceting.
double fe_surface_integral(const mesh::Mesh& m, const AdhesionLaw& law) {
  const ContactSurface tip = make_surface(m, "tip", {"tip_surface"});
  const int n = 32;
  double F = 0.0;
  for (int f = 0; f < tip.face_count(); ++f) {
    const int* fn = &tip.face_nodes[4 * f];
    const double sa[4] = {-1, 1, 1, -1}, ta[4] = {-1, -1, 1, 1};
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const double xi = -1 + (2 * i + 1.0) / n, eta = -1 + (2 * j + 1.0) / n;
        double x[3] = {}, xs[3] = {}, xe[3] = {};
        for (int a = 0; a < 4; ++a)
          for (int k = 0; k < 3; ++k) {
            const double X = m.coordinates[3 * fn[a] + k];
            x[k] += 0.25 * (1 + sa[a] * xi) * (1 + ta[a] * eta) * X;
            xs[k] += 0.25 * sa[a] * (1 + ta[a] * eta) * X;
            xe[k] += 0.25 * ta[a] * (1 + sa[a] * xi) * X;
          }
        const double c[3] = {xs[1] * xe[2] - xs[2] * xe[1], xs[2] * xe[0] - xs[0] * xe[2], xs[0] * xe[1] - xs[1] * xe[0]};
        if (c[2] >= 0.0) continue;  // the column's sides and top do not face the flat
        const double dA = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) * (4.0 / (n * n));
        F += adhesive_traction(x[2], law) * dA;
      }
  }
  return F;
}

// Summed adhesive force (z component on the tip surface) of the sphere R above the flat, both
// rigid (one compute_forces call at the reference coordinates), attraction reported positive.
double tip_force(const mesh::Mesh& m, Enforcement enforcement, const AdhesionLaw& law) {
  const std::vector<double> mass(m.node_count(), 1e-24);
  ContactManager manager =
      test::one_interaction(m, "tip_surface", "substrate_top", test::adhesion_settings(law, enforcement), mass);
  std::vector<double> force(m.coordinates.size(), 0.0);
  manager.compute_forces(m.coordinates.data(), nullptr, force.data());
  return -test::force_sum(force, m.side_set_nodes("tip_surface"), 2);
}

// Exact sphere, applied law, true (not projected) area like both FE rules:
// F = int sigma_s(g(r)) 2 pi r dr / cos(theta), g(r) = D + R - sqrt(R^2 - r^2), cos(theta) = sqrt(R^2 - r^2) / R.
double exact_force(double D, const AdhesionLaw& law) {
  const double R = 27 * nm;
  double F = 0.0;
  const int n = 400000;
  const double r_max = 15 * nm, dr = r_max / n;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) * dr;
    const double root = std::sqrt(R * R - r * r);
    F += adhesive_traction(D + R - root, law) * 2 * M_PI * r * dr * R / root;
  }
  return F;
}

// Sphere handle (docs/theory.md 6.5) on coarse meshes. The face rule integrates the law over the FE
// surface to 0.2 % at every element size (asserted); against the sphere both rules also carry the
// faceting of the FE surface: bilinear faces lie up to h^2 / (4R) (the face diagonal's sagitta,
// 0.037 nm = 0.19 z0 at h = 2 nm) above the sphere, which lowers the force by 8-21 % at h = 2-3 nm.
// The nodal rule samples the law at the nodes, which lie on the sphere: it misses the faceting but
// also the law's variation between nodes; numbers in contact/models/README.md.
TEST(FaceAdhesion, SphereAboveFlatCoarseMeshes) {
  const AdhesionLaw law{W, z0, 20 * z0};
  // h = 0.5 nm (both rules within 0.8 % of the sphere, contact/models/README.md) is left out of
  // CI: its mesh makes this test 4x longer; adhesion_manager_test checks the fine nodal case.
  for (double h : {1.0 * nm, 2.0 * nm, 3.0 * nm})
    for (double D : {0.0, 0.2 * nm}) {
      const Case c = make_case(h, D);
      const double exact = exact_force(D, law);
      const double fe = fe_surface_integral(c.mesh, law);
      const double nodal = tip_force(c.mesh, Enforcement::node_to_face, law);
      const double face = tip_force(c.mesh, Enforcement::mortar, law);
      std::printf("h = %.2f nm, D = %.2f nm: sphere %.4g N, FE surface %+.2f %%; vs FE surface: nodal %+.2f %%, "
                  "face %+.2f %%; vs sphere: nodal %+.2f %%, face %+.2f %%\n",
                  h / nm, D / nm, exact, 100 * (fe / exact - 1), 100 * (nodal / fe - 1), 100 * (face / fe - 1),
                  100 * (nodal / exact - 1), 100 * (face / exact - 1));
      EXPECT_NEAR(face / fe, 1.0, 0.002) << "h = " << h / nm << " nm, D = " << D / nm << " nm";
      // Nodes on the sphere: at h = 1 nm the nodal rule still meets the handle's 2 % (0.04 % here);
      // the face rule's distance from the sphere is the faceting, fe / exact, printed above.
      if (h <= 1.0 * nm) {
        EXPECT_NEAR(nodal / exact, 1.0, 0.02);
      }
    }
}

// A rigid flat inclined at angle alpha (sin alpha = 0.1) above the rigid flat, lowest edge at gap
// D: the FE surface is exact (flat faces), so only the integration rule errs. Closed form, with
// the applied law's potential E(g) (dE/dg = sigma_s): F = (L_y / sin alpha) [E(D + L sin alpha) - E(D)].
// Element sizes 0.5-2 nm, i.e. the gap changes by 0.25-1 z0 across an element.
TEST(FaceAdhesion, InclinedFlatAboveFlat) {
  const AdhesionLaw law{W, z0, 20 * z0};
  const double sin_a = 0.1, cos_a = std::sqrt(1 - sin_a * sin_a), L = 10 * nm;
  for (int intervals : {5, 10, 20})
    for (double D : {0.0, 0.1 * nm, 0.4 * nm}) {
      // The slave slab L x 10 nm from x = 0, grid intervals x intervals, tilted about the y axis
      // (lowest edge at x = -5 nm, z = D).
      mesh::Mesh m = test::two_flats({.slave_intervals = {intervals, intervals}, .slave_origin = {0, -5 * nm},
                                      .slave_size = {L, 10 * nm}});
      for (int n : m.node_sets.at("upper_all")) {
        const double x = m.coordinates[3 * n], z = m.coordinates[3 * n + 2];
        m.coordinates[3 * n] = -5 * nm + x * cos_a - z * sin_a;
        m.coordinates[3 * n + 2] = D + x * sin_a + z * cos_a;
      }
      auto force = [&](Enforcement e) {
        const std::vector<double> mass(m.node_count(), 1e-24);
        ContactManager manager = test::one_interaction(m, "upper_zmin", "lower_zmax", test::adhesion_settings(law, e), mass);
        std::vector<double> f(m.coordinates.size(), 0.0);
        manager.compute_forces(m.coordinates.data(), nullptr, f.data());
        const double fz = test::force_sum(f, m.side_set_nodes("upper_zmin"), 2);
        double total = 0.0;
        for (std::size_t k = 2; k < f.size(); k += 3) total += f[k];
        EXPECT_NEAR(total / fz, 0.0, 1e-12);  // the master receives the reaction exactly
        return -fz;
      };
      const double exact = 10 * nm / sin_a * (adhesive_energy(D + L * sin_a, law) - adhesive_energy(D, law));
      const double nodal = force(Enforcement::node_to_face), face = force(Enforcement::mortar);
      std::printf("inclined flat, h = %.2f nm (gap change %.2f z0 per element), D = %.2f nm: exact %.4g N, "
                  "nodal %+.3f %%, face %+.3f %%\n",
                  L / intervals / nm, L / intervals * sin_a / z0, D / nm, exact, 100 * (nodal / exact - 1),
                  100 * (face / exact - 1));
      EXPECT_NEAR(face / exact, 1.0, 0.005) << intervals << " " << D / nm;
      EXPECT_LT(std::abs(face / exact - 1), std::abs(nodal / exact - 1)) << intervals << " " << D / nm;
    }
}

}  // namespace
}  // namespace tribex::contact
