// SPDX-License-Identifier: MIT
// tribex layered (tools/layered, docs/theory.md 11.4): the stack's Hankel-space compliance against its
// closed forms and limits, the contact solution against Hertz, the thin- and thick-layer limits, the
// flat-punch stiffness against Gao, Chiu & Lee (1992) and the quadrature's convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <numbers>

#include "tools/layered/contact.hpp"
#include "tools/layered/curve.hpp"
#include "tools/layered/kernel.hpp"

namespace tribex::layered {
namespace {

const Elastic si{161e9, 0.23};
const Elastic coating{8e9, 0.4};

Stack layer_on(const Elastic& layer, double h, const Elastic& base) { return Stack{{Layer{h, layer}}, base}; }

TEST(LayeredKernel, HomogeneousWhenTheLayerIsTheSubstrate) {
  for (double nu : {0.0, 0.23, 0.4, 0.49}) {
    const Elastic m{100e9, nu};
    const Stack two{{Layer{1e-9, m}, Layer{3e-9, m}}, m};
    for (double t : {1e-4, 1e-2, 0.3, 1.0, 5.0, 40.0, 400.0}) {
      EXPECT_NEAR(surface_compliance(layer_on(m, 2e-9, m), t / 2e-9) * m.plane_strain(), 1.0, 1e-12) << nu << " " << t;
      EXPECT_NEAR(surface_compliance(two, t / 2e-9) * m.plane_strain(), 1.0, 1e-12) << nu << " " << t;
    }
  }
}

TEST(LayeredKernel, LayerOnRigidBaseMatchesTheClosedForm) {
  for (double nu : {0.0, 0.23, 0.4, 0.49}) {
    const Layer l{2e-9, {8e9, nu}};
    const Stack s{{l}, std::nullopt};
    for (double t = 1e-5; t < 300; t *= 1.7) {
      const double c = surface_compliance(s, t / l.thickness), ref = rigid_base_layer_compliance(l, t / l.thickness);
      EXPECT_NEAR(c * l.material.plane_strain(), ref * l.material.plane_strain(), 1e-12) << nu << " " << t;
    }
    // Winkler limit of the closed form (docs/theory.md 11.4.1): C -> xi h (1 - 2nu)(1 + nu)/(2 E (1 - nu)) as xi h -> 0.
    const double t = 1e-6, m = l.material.youngs * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
    EXPECT_NEAR(rigid_base_layer_compliance(l, t / l.thickness) / (t / 2.0 / m), 1.0, 1e-5);
  }
}

TEST(LayeredKernel, ThinAndThickLayerLimitsAndStackSplitting) {
  const Stack s = layer_on(coating, 2e-9, si);
  EXPECT_NEAR(surface_compliance(s, 1e-6 / 2e-9) * si.plane_strain(), 1.0, 1e-4);    // xi h -> 0: substrate
  EXPECT_NEAR(surface_compliance(s, 30.0 / 2e-9) * coating.plane_strain(), 1.0, 1e-20);  // xi h -> inf: layer
  // A layer split into two bonded layers of the same material is the same stack.
  const Stack split{{Layer{0.7e-9, coating}, Layer{1.3e-9, coating}}, si};
  for (double t : {1e-3, 0.1, 1.0, 3.0, 20.0})
    EXPECT_NEAR(surface_compliance(split, t / 2e-9) / surface_compliance(s, t / 2e-9), 1.0, 1e-12) << t;
}

double hertz_load(double e_eff, double a, double r) { return 4.0 * e_eff * a * a * a / (3.0 * r); }

TEST(LayeredContact, HertzWhenTheLayerHasTheSubstratesMaterial) {
  const double r = 27e-9, a = 3e-9;
  Contact c(layer_on(si, 2e-9, si), si, r);
  const double e_eff = 1.0 / (2.0 / si.plane_strain());
  const auto s = c.sphere(a);
  EXPECT_NEAR(s.load / hertz_load(e_eff, a, r), 1.0, 1e-6);
  EXPECT_NEAR(s.approach / (a * a / r), 1.0, 1e-6);
  const auto t = c.sphere_at_load(50e-9, 2e-9);
  EXPECT_NEAR(t.radius / std::cbrt(3.0 * 50e-9 * r / (4.0 * e_eff)), 1.0, 1e-6);
  // Hertz pressure p0 sqrt(1 - r^2/a^2), p0 = 2 E_eff a/(pi R).
  const auto p = c.pressure(s, {0.0, 1e-9, 2.5e-9});
  const double p0 = 2.0 * e_eff * a / (std::numbers::pi * r);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double x = std::vector<double>{0.0, 1e-9, 2.5e-9}[i];
    EXPECT_NEAR(p[i] / (p0 * std::sqrt(1 - x * x / (a * a))), 1.0, 1e-6) << x;
  }
}

// Relative load and approach differences from Hertz at fixed contact radius, for layer thickness h.
std::pair<double, double> deviation(const Elastic& layer, double h, double a, const Elastic& reference) {
  Contact c(layer_on(layer, h, si), si, 27e-9);
  const double e_eff = 1.0 / (1.0 / si.plane_strain() + 1.0 / reference.plane_strain());
  const auto s = c.sphere(a);
  return {s.load / hertz_load(e_eff, a, 27e-9) - 1.0, s.approach / (a * a / 27e-9) - 1.0};
}

TEST(LayeredContact, ThinLayerGivesTheSubstratesHertz) {
  // A thin layer adds its (Winkler) compliance h p/M to the approach, first order in (E_eff/M)(h/a), plus
  // an edge correction of order (h/a) ln(h/a) (the pressure's square-root edge seen through a kernel of
  // width h): over a factor 4 in h the deviation falls by 2.5 (h ln h) to 4 (h). Measured: 3.1 and 2.9.
  // With a 100 GPa layer on Si, (E_eff/M)(h/a) is small already at h/a = 0.1.
  const double a = 3e-9;
  const Elastic mild{100e9, 0.3};
  const auto d1 = deviation(mild, 0.1 * a, a, si), d2 = deviation(mild, 0.025 * a, a, si);
  std::printf("thin 100 GPa layer: h/a = 0.1: dP/P %.4g, ddelta/delta %.4g; h/a = 0.025: %.4g, %.4g\n", d1.first,
              d1.second, d2.first, d2.second);
  EXPECT_GT(d1.first / d2.first, 2.5);
  EXPECT_LT(d1.first / d2.first, 4.0);
  EXPECT_GT(d1.second / d2.second, 2.5);
  EXPECT_LT(d1.second / d2.second, 4.0);
  EXPECT_LT(std::abs(d2.first), 0.02);
  // The coated study's 8 GPa coating (M_c = 17 GPa, E_eff/M_c = 5): out of the first-order regime at
  // these h/a, but the deviation falls monotonically towards the substrate's Hertz.
  double last = 1.0;
  for (double r : {0.1, 0.05, 0.025}) {
    const auto d = deviation(coating, r * a, a, si);
    std::printf("thin 8 GPa coating: h/a = %g: dP/P %.4g, ddelta/delta %.4g\n", r, d.first, d.second);
    EXPECT_LT(std::abs(d.first), 0.8 * last);
    last = std::abs(d.first);
  }
}

TEST(LayeredContact, ThickLayerGivesTheLayersHertz) {
  // The distant substrate shifts the surface nearly uniformly (O(a/h) in the approach) and bends it
  // only at O((a/h)^3): the load at a given radius converges at third order.
  const double a = 3e-9;
  const auto d1 = deviation(coating, 10 * a, a, coating), d2 = deviation(coating, 100 * a, a, coating);
  std::printf("thick layer: h/a = 10: dP/P %.4g, ddelta/delta %.4g; h/a = 100: %.4g, %.4g\n", d1.first, d1.second,
              d2.first, d2.second);
  EXPECT_NEAR(d1.second / d2.second, 10.0, 1.0);
  EXPECT_NEAR(std::log10(d1.first / d2.first), 3.0, 0.1);
  EXPECT_LT(std::abs(d2.first), 1e-5);
  EXPECT_LT(std::abs(d2.second), 0.01);
}

// Gao, Chiu & Lee (1992), Int. J. Solids Struct. 29, 2471: to first order in mu_f - mu_s, a flat punch of
// radius a on a film (thickness t) over a substrate of the same Poisson ratio sees
// mu = mu_s + (mu_f - mu_s) I0(t/a), I0(x) = (2/pi) atan x + [(1 - 2nu) x ln((1 + x^2)/x^2) - x/(1 + x^2)]/(2 pi (1 - nu)).
double gao_i0(double x, double nu) {
  return 2.0 / std::numbers::pi * std::atan(x) +
         ((1 - 2 * nu) * x * std::log((1 + x * x) / (x * x)) - x / (1 + x * x)) / (2 * std::numbers::pi * (1 - nu));
}

TEST(LayeredContact, FlatPunchMatchesGaoChiuLeeWeights) {
  const double a = 2e-9, eps = 1e-3;
  const Elastic rigid{std::numeric_limits<double>::infinity(), 0.3};
  for (double nu : {0.2, 0.35}) {
    const Elastic base{100e9, nu};
    for (double x : {0.1, 0.3, 1.0, 3.0}) {
      auto stiffness = [&](double factor) {
        Contact c(layer_on({100e9 * factor, nu}, x * a, base), rigid, 1.0);
        return c.flat_punch_stiffness(a);
      };
      const double s0 = stiffness(1.0);
      EXPECT_NEAR(s0 / (2.0 * a * base.plane_strain()), 1.0, 1e-10);  // Boussinesq: S = 2 a E*
      const double weight = (stiffness(1 + eps) - stiffness(1 - eps)) / (2 * eps * s0);
      EXPECT_NEAR(weight, gao_i0(x, nu), 1e-5) << "nu " << nu << " t/a " << x;
    }
  }
}

TEST(LayeredContact, ConvergedInNodesAndHankelPoints) {
  // The coated study's case 1 (R = 27 nm, h_c = 2 nm, E_c = 8 GPa on Si): f at the defaults against
  // twice the nodes, twice the Hankel points per panel, a 1.5x longer xi range and panels half as wide.
  const Stack s = layer_on(coating, 2e-9, si);
  Settings fine;
  fine.nodes = 48;
  fine.hankel_per_panel = 32;
  fine.hankel_extent = 60;
  fine.panels_per_radius = 2.0;
  Contact c(s, si, 27e-9), f(s, si, 27e-9, fine);
  const double scale = coating.plane_strain() * 4e-18;
  const auto x = load_curve(c, scale, {0.02, 0.2, 1.59, 3.0});
  const auto y = load_curve(f, scale, {0.02, 0.2, 1.59, 3.0});
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i].f, y[i].f, 1e-10) << x[i].p_tilde;
  // and p >= 0 inside the contact, integrating to the load
  const auto sol = c.sphere_at_load(1.59 * scale, 3e-9);
  std::vector<double> r;
  const gw::QuadratureRule q = gw::gauss_legendre_rule(40, 0.0, sol.radius);
  const auto p = c.pressure(sol, q.x);
  double load = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_GE(p[i], 0.0);
    load += 2 * std::numbers::pi * q.x[i] * p[i] * q.w[i];
  }
  EXPECT_NEAR(load / sol.load, 1.0, 1e-4);  // sqrt edge: Gauss-Legendre converges slowly here
}

}  // namespace
}  // namespace tribex::layered
