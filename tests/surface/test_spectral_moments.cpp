// SPDX-License-Identifier: MIT
// Spectral moments of synthetic Gaussian random surfaces against the analytic PSD integrals of
// docs/theory.md 10.1: m0 = 2 pi int q C dq, m2 = pi int q^3 C dq, m4 = (3 pi / 4) int q^5 C dq.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesh/afm/preprocess.hpp"
#include "synthetic_surface.hpp"
#include "contact/rough/gw_integrals.hpp"
#include "tools/surface/spectral_moments.hpp"

using namespace tribex;
using surface::Direction;

namespace {
struct Expected { double m0, m2, m4; };

Expected psd_integrals(const std::function<double(double)>& c, double q_max) {
  auto i = [&](int p) { return gw::gauss_legendre([&](double q) { return std::pow(q, p) * c(q); }, 0.0, q_max, 400); };
  return {2 * M_PI * i(1), M_PI * i(3), 0.75 * M_PI * i(5)};
}

void check(const mesh::afm::HeightMap& raw, const Expected& e, const char* what) {
  SCOPED_TRACE(what);
  // The synthetic map is periodic and has no tilt: only the mean is removed. (Plane levelling of a finite
  // map also removes part of the longest-wavelength modes, a few % of m0 when the PSD has power at the
  // box scale; that is a property of levelling, not of the moment estimator tested here.)
  const auto map = mesh::afm::remove_mean(raw);
  for (Direction dir : {Direction::x, Direction::y}) {
    const auto m = surface::profile_moments(map, dir);
    std::printf("  %s along %s: m0 %.4f m2 %.4f m4 %.4f alpha %.4f (measured / analytic)\n", what,
                dir == Direction::x ? "x" : "y", m.m0 / e.m0, m.m2 / e.m2, m.m4 / e.m4,
                (m.m0 * m.m4 / (m.m2 * m.m2)) / (e.m0 * e.m4 / (e.m2 * e.m2)));
    EXPECT_NEAR(m.m0 / e.m0, 1.0, 0.02);
    EXPECT_NEAR(m.m2 / e.m2, 1.0, 0.02);
    EXPECT_NEAR(m.m4 / e.m4, 1.0, 0.02);
    EXPECT_NEAR((m.m0 * m.m4 / (m.m2 * m.m2)) / (e.m0 * e.m4 / (e.m2 * e.m2)), 1.0, 0.05);
  }
}
}  // namespace

TEST(SpectralMoments, GaussianPsdSurfacesOfSeveralSizesAndSeeds) {
  // C(q) = C0 exp(-q^2/qc^2): m0 = pi C0 qc^2, m2 = pi C0 qc^4 / 2, m4 = 3 pi C0 qc^6 / 4, alpha = 3 exactly.
  for (std::size_t n : {256u, 512u}) {
    const double d = 1e-9, L = static_cast<double>(n) * d;
    const double qc = (n == 256 ? 6.0 : 9.0) * 2 * M_PI / L;  // roll-off resolved: qc d = 0.15 and 0.11
    const double c0 = 1e-36;
    auto psd = [&](double q) { return c0 * std::exp(-q * q / (qc * qc)); };
    const Expected e{M_PI * c0 * qc * qc, M_PI * c0 * std::pow(qc, 4) / 2, 0.75 * M_PI * c0 * std::pow(qc, 6)};
    const Expected numeric = psd_integrals(psd, 10 * qc);  // the quadrature helper agrees with the closed form
    EXPECT_NEAR(numeric.m4 / e.m4, 1.0, 1e-10);
    EXPECT_NEAR(e.m0 * e.m4 / (e.m2 * e.m2), 3.0, 1e-12);
    for (unsigned seed : {1u, 2u, 3u}) check(test::synthetic_surface(n, d, psd, seed), e, "gaussian psd");
  }
}

TEST(SpectralMoments, PowerLawPsdWithRollOffAndCutOff) {
  // Self-affine (H = 0.8) between a roll-off qr and a smooth cut-off qs: larger bandwidth alpha.
  const std::size_t n = 512;
  const double d = 2e-9, L = static_cast<double>(n) * d, dq = 2 * M_PI / L;
  const double qr = 6 * dq, qs = 0.1 / d, H = 0.8;
  auto psd = [&](double q) { return 1e-36 * std::pow(1 + (q / qr) * (q / qr), -(1 + H)) * std::exp(-(q / qs) * (q / qs)); };
  const Expected e = psd_integrals(psd, 12 * qs);
  EXPECT_GT(e.m0 * e.m4 / (e.m2 * e.m2), 3.5);  // distinct from the Gaussian PSD's alpha = 3
  for (unsigned seed : {7u, 8u}) check(test::synthetic_surface(n, d, psd, seed), e, "power-law psd");
}

TEST(SpectralMoments, SummitRelationsReproduceThePhysicsVerificationHandle) {
  // docs/theory.md 10.5: m0 = 1 nm^2, m2 = 0.01, m4 = 1e-3 nm^-2 (alpha = 10).
  const surface::Moments m{1e-18, 0.01, 1e-3 * 1e18};
  const auto s = surface::summit_statistics(m);
  EXPECT_NEAR(s.alpha, 10.0, 1e-12);
  EXPECT_NEAR(s.density * 1e-18, 3.0629e-3, 0.5e-7);
  EXPECT_NEAR(s.radius * 1e9, 21.019, 0.5e-3);
  EXPECT_NEAR(s.sigma_s * 1e9, 0.95411, 0.5e-5);
  EXPECT_NEAR(s.mean_height * 1e9, 0.71365, 0.5e-5);
}

TEST(SpectralMoments, CosineProfileHasExactDiscreteMoments) {
  // z = A cos(k x) sampled at spacing d: central differences give m2 = A^2 sin^2(kd)/(2 d^2) and
  // m4 = A^2 (2 - 2 cos kd)^2 / (2 d^4) exactly on whole periods.
  mesh::afm::HeightMap m;
  m.nx = 64; m.ny = 4; m.dx = m.dy = 1e-9;
  const double A = 2e-9, k = 2 * M_PI * 4 / (64 * 1e-9), d = 1e-9;
  for (std::size_t iy = 0; iy < m.ny; ++iy)
    for (std::size_t ix = 0; ix < m.nx; ++ix) m.heights.push_back(A * std::cos(k * d * static_cast<double>(ix)));
  const auto mx = surface::profile_moments(m, Direction::x);
  EXPECT_NEAR(mx.m0 / (A * A / 2), 1.0, 1e-12);
  EXPECT_NEAR(mx.m2 / (A * A * std::pow(std::sin(k * d), 2) / (2 * d * d)), 1.0, 0.05);  // interior points only
  EXPECT_NEAR(mx.m4 / (A * A * std::pow(2 - 2 * std::cos(k * d), 2) / (2 * std::pow(d, 4))), 1.0, 0.05);
  EXPECT_NEAR(surface::profile_moments(m, Direction::y).m2, 0.0, 1e-30);
}
