// SPDX-License-Identifier: MIT
// J2 plasticity at one material point against the closed forms of docs/theory.md 3.3:
// uniaxial stress (sigma = Y + E_t (eps - Y/E), E_t = E K/(E + K)), simple shear
// (tau = tau_y + G_t (gamma - gamma_y), G_t = mu (K/3)/(mu + K/3), tau_y = Y/sqrt(3)), elastic
// unloading, the plastic work against its closed form, and two points in one register (double2)
// bitwise as alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "inputs/units.hpp"
#include "materials/j2_plasticity.hpp"
#include "materials/material.hpp"

namespace tribex::materials {
namespace {

constexpr double E = 161e9, nu = 0.23, Y = 4e9, K = 20e9;

KeyValues silicon_keys() {
  KeyValues v;
  v.numbers = {{"yield stress", Y}, {"hardening modulus", K}};
  return v;
}
J2Plasticity silicon_like() { return J2Plasticity::make(lame_lambda(E, nu), lame_mu(E, nu), 2330.0, silicon_keys()); }

// One increment of uniaxial stress: the lateral strain that makes sigma_yy = sigma_zz = 0, found
// by Newton on a copy of the state at n (the stress is piecewise linear in the lateral strain).
struct UniaxialPoint {
  std::array<double, 7> state{};
  double lateral = 0.0;
  double dissipated = 0.0;  // sum of the updates' plastic work (J/m^3)
  double stress = 0.0;

  void strain_to(const J2Plasticity& m, double eps) {
    auto sigma_yy = [&](double lat, std::array<double, 7>& st, double& d, double& sxx) {
      const double H[9] = {eps, 0, 0, 0, lat, 0, 0, 0, lat};
      double S[9];
      m.force_stress(H, st.data(), 0.0, S, d);
      sxx = S[0];
      return S[4];
    };
    for (int it = 0; it < 50; ++it) {
      std::array<double, 7> a = state, b = state;
      double da, db, sa, sb;
      const double h = 1e-9 * std::max(std::abs(eps), 1e-12);
      const double fa = sigma_yy(lateral, a, da, sa), fb = sigma_yy(lateral + h, b, db, sb);
      if (std::abs(fa) < 1e-9 * Y) break;
      lateral -= fa * h / (fb - fa);
    }
    double d, sxx;
    sigma_yy(lateral, state, d, sxx);
    dissipated += d;
    stress = sxx;
  }
};

TEST(J2Plasticity, UniaxialStressFollowsTheBilinearClosedForm) {
  const J2Plasticity m = silicon_like();
  UniaxialPoint point;
  const double eps_y = Y / E, Et = E * K / (E + K);
  double worst = 0.0;
  for (int n = 1; n <= 400; ++n) {
    const double eps = 4.0 * eps_y * n / 400.0;
    point.strain_to(m, eps);
    const double expected = eps <= eps_y ? E * eps : Y + Et * (eps - eps_y);
    worst = std::max(worst, std::abs(point.stress - expected) / Y);
  }
  EXPECT_LT(worst, 1e-8);
  // Plastic strain (sigma - Y)/K and the equivalent plastic strain alpha equal to it.
  const double eps_p = (point.stress - Y) / K;
  EXPECT_NEAR(point.state[0], eps_p, 1e-8 * eps_p);
  EXPECT_NEAR(point.state[1], -0.5 * eps_p, 1e-8 * eps_p);
  EXPECT_NEAR(point.state[6], eps_p, 1e-8 * eps_p);
  // Plastic work: integral of sigma d eps_p = Y eps_p + K eps_p^2 / 2, which the midpoint rule in
  // alpha sums exactly (the sum telescopes): round-off only.
  const double work = Y * eps_p + 0.5 * K * eps_p * eps_p;
  EXPECT_NEAR(point.dissipated, work, 1e-9 * work);

  // Unloading is elastic with slope E, leaving the plastic strain.
  const double top = point.stress, top_eps = 4.0 * eps_y;
  for (int n = 1; n <= 50; ++n) {
    const double eps = top_eps - 1.5 * eps_y * n / 50.0;
    const double d_before = point.dissipated;
    point.strain_to(m, eps);
    EXPECT_NEAR(point.stress, top - E * (top_eps - eps), 1e-8 * Y);
    EXPECT_EQ(point.dissipated, d_before);
  }
  EXPECT_NEAR(point.state[0], eps_p, 1e-8 * eps_p);
}

TEST(J2Plasticity, SimpleShearFollowsTheBilinearClosedForm) {
  const J2Plasticity m = silicon_like();
  const double mu = lame_mu(E, nu), tau_y = Y / std::sqrt(3.0), gamma_y = tau_y / mu;
  const double Gt = mu * (K / 3.0) / (mu + K / 3.0);
  std::array<double, 7> state{};
  double worst = 0.0, dissipated = 0.0, last_tau = 0.0;
  for (int n = 1; n <= 300; ++n) {
    const double gamma = 5.0 * gamma_y * n / 300.0;
    const double H[9] = {0, gamma, 0, 0, 0, 0, 0, 0, 0};  // u_x = gamma y
    double S[9], d;
    m.force_stress(H, state.data(), 0.0, S, d);
    dissipated += d;
    const double expected = gamma <= gamma_y ? mu * gamma : tau_y + Gt * (gamma - gamma_y);
    worst = std::max(worst, std::abs(S[1] - expected) / tau_y);
    EXPECT_NEAR(S[0], 0.0, 1e-6) << "no normal stress in small-strain simple shear";
    EXPECT_NEAR(S[4], 0.0, 1e-6);
    last_tau = S[1];
  }
  EXPECT_LT(worst, 1e-10);
  // gamma_p = 3 (tau - tau_y)/K; alpha = gamma_p / sqrt(3); work = tau_y gamma_p + K gamma_p^2 / 6.
  const double gamma_p = 3.0 * (last_tau - tau_y) / K;
  EXPECT_NEAR(2.0 * state[3], gamma_p, 1e-9 * gamma_p);
  EXPECT_NEAR(state[6], gamma_p / std::sqrt(3.0), 1e-9 * gamma_p);
  const double work = tau_y * gamma_p + K * gamma_p * gamma_p / 6.0;
  EXPECT_NEAR(dissipated, work, 1e-9 * work);
}

TEST(J2Plasticity, PerfectPlasticityHoldsTheYieldStress) {
  KeyValues perfect;
  perfect.numbers = {{"yield stress", Y}, {"hardening modulus", 0.0}};
  const J2Plasticity m = J2Plasticity::make(lame_lambda(E, nu), lame_mu(E, nu), 2330.0, perfect);
  std::array<double, 7> state{};
  double S[9], d;
  for (int n = 1; n <= 100; ++n) {
    const double gamma = 0.1 * n / 100.0;
    const double H[9] = {0, 0, gamma, 0, 0, 0, 0, 0, 0};  // u_x = gamma z
    m.force_stress(H, state.data(), 0.0, S, d);
  }
  EXPECT_NEAR(S[2], Y / std::sqrt(3.0), 1e-9 * Y);
  EXPECT_EQ(S[6], S[2]);
}

TEST(J2Plasticity, PairOfPointsInOneRegisterIsBitwiseTheLonePoints) {
  const J2Plasticity m = silicon_like();
  const double Ha[9] = {0.03, 0.004, -0.002, 0.001, -0.01, 0.005, 0.0, 0.002, -0.006};
  const double Hb[9] = {0.001, 0.0, 0.0, 0.0, 0.0005, 0.0, 0.0, 0.0, -0.0002};  // stays elastic
  double sa[7] = {1e-4, -5e-5, -5e-5, 0, 0, 2e-5, 1.2e-4}, sb[7] = {};
  double2 H2[9], s2[7], S2[9], d2;
  for (int k = 0; k < 9; ++k) H2[k] = double2{Ha[k], Hb[k]};
  for (int k = 0; k < 7; ++k) s2[k] = double2{sa[k], sb[k]};
  const double2 W2 = m.force_stress(H2, s2, 0.0, S2, d2);
  double Sa[9], Sb[9], da, db;
  const double Wa = m.force_stress(Ha, sa, 0.0, Sa, da);
  const double Wb = m.force_stress(Hb, sb, 0.0, Sb, db);
  EXPECT_EQ(W2[0], Wa);
  EXPECT_EQ(W2[1], Wb);
  EXPECT_EQ(d2[0], da);
  EXPECT_EQ(d2[1], db);
  EXPECT_GT(da, 0.0);
  EXPECT_EQ(db, 0.0);
  for (int k = 0; k < 9; ++k) {
    EXPECT_EQ(S2[k][0], Sa[k]);
    EXPECT_EQ(S2[k][1], Sb[k]);
  }
  for (int k = 0; k < 7; ++k) {
    EXPECT_EQ(s2[k][0], sa[k]);
    EXPECT_EQ(s2[k][1], sb[k]);
  }
}

TEST(J2Plasticity, ReturnIsIdempotentAtTheSameStrain) {
  // A restart recomputes the forces at the restored displacement: a second update at the same H
  // must add (next to) nothing.
  const J2Plasticity m = silicon_like();
  const double H[9] = {0.05, 0.01, 0.0, 0.0, -0.02, 0.0, 0.0, 0.0, -0.02};
  std::array<double, 7> state{};
  double S1[9], S2[9], d1, d2;
  m.force_stress(H, state.data(), 0.0, S1, d1);
  const auto after = state;
  m.force_stress(H, state.data(), 0.0, S2, d2);
  EXPECT_GT(d1, 0.0);
  EXPECT_LT(d2, 1e-12 * d1);
  for (int k = 0; k < 9; ++k) EXPECT_NEAR(S2[k], S1[k], 1e-12 * Y);
  for (int k = 0; k < 7; ++k) EXPECT_NEAR(state[k], after[k], 1e-15);
}

TEST(MaterialRegistry, OneListDrivesNamesParametersAndConstruction) {
  const auto names = model_names();
  ASSERT_EQ(static_cast<int>(names.size()), model_count);
  EXPECT_EQ(names[0], "elastic");
  EXPECT_EQ(model_index("neo_hookean"), 1);
  const int j2 = model_index("j2_plasticity");
  ASSERT_GE(j2, 0);
  ASSERT_EQ(model_keys(j2).size(), 2u);
  EXPECT_EQ(model_keys(j2)[0].key, "yield stress");
  EXPECT_EQ(model_index("no_such_model"), -1);
  const Material made = make_material(j2, E, nu, 2330.0, silicon_keys());
  ASSERT_TRUE(std::holds_alternative<J2Plasticity>(made));
  EXPECT_EQ(std::get<J2Plasticity>(made).yield_stress, Y);
  EXPECT_EQ(std::get<J2Plasticity>(made).hardening_modulus, K);
  EXPECT_EQ(model_name(made), "j2_plasticity");
  EXPECT_EQ(state_size_of(made), 7);
  EXPECT_TRUE(dissipates(made));
  EXPECT_EQ(state_size_of(make_material(0, E, nu, 2330.0, {})), 0);
}

}  // namespace
}  // namespace tribex::materials

namespace tribex::materials {
namespace {

TEST(MaterialRegistry, EveryDeclaredKeyHasAParsableDefaultOrIsRequired) {
  // The deck builder reads a model's defaults with inputs::parse_quantity: a default it cannot
  // parse would silently become 0, so every one must parse, to a number within its bound.
  for (int m = 0; m < model_count; ++m)
    for (const KeyDecl& d : model_keys(m)) {
      std::string why;
      if (!d.unit.empty()) {
        EXPECT_TRUE(inputs::parse_unit(d.unit, &why)) << d.key << ": " << why;
      }
      if (d.default_text.empty()) continue;
      const auto q = inputs::parse_quantity(d.default_text, &why);
      ASSERT_TRUE(q) << d.key << ": " << why;
      EXPECT_TRUE(d.lower_open ? q->value > d.lower_bound : q->value >= d.lower_bound) << d.key;
    }
}

}  // namespace
}  // namespace tribex::materials
