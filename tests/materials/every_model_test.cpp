// SPDX-License-Identifier: MIT
// Every material model of the list (materials/material.hpp `Material`), each built from its declared
// keys alone (every_model_support.hpp): a typed test over the variant's alternatives, so a new model
// is covered with no edit here. What each must satisfy (materials/README.md "The interface"):
//  - zero stress and energy at the identity (H = 0, fresh state);
//  - the stress is the gradient of the returned energy, S_iJ = dW/dH_iJ, against a central
//    difference of W (hyperelastic models at any H; a model with state in its elastic range, where
//    the returned stored energy is the potential of the stress), and the Cauchy stress for output
//    agrees with it (sigma = S small strain, sigma = P F^T / J finite strain);
//  - a finite-strain model is objective: a rotation Q of F rotates P and keeps W;
//  - two (double2), four (double4) and eight (double8) points in one register give bitwise what
//    each gives alone (stress, energy, dissipation, state), over two updates;
//  - wave_modulus(H) is the P-wave modulus of the tangent at H, the stable step's rule
//    (materials/README.md, docs/theory.md 1.4): M = max over unit n of n_i n_j c_ijkl n_k n_l with c
//    from a central difference of the stress: c = dsigma/dH (small strain), or
//    c_ijkl = (1/J) F_jJ F_lL dP_iJ/dF_kL - delta_ik sigma_jl (finite strain: the spatial tangent of
//    the Oldroyd rate of Kirchhoff stress over J); equal within 1e-6 in the elastic range, and an
//    upper bound of it (1e-6) where a model with state flows plastically.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "tests/materials/every_model_lanes.hpp"
#include "tests/materials/every_model_support.hpp"

namespace tribex::materials {
namespace {

using namespace every_model;

template <class V>
struct TypesOf;
template <class... M>
struct TypesOf<std::variant<M...>> {
  using type = ::testing::Types<M...>;
};
struct DeckName {
  template <class M>
  static std::string GetName(int) {
    return std::string(M::deck_name);
  }
};

template <class M>
class EveryModel : public ::testing::Test {};
TYPED_TEST_SUITE(EveryModel, TypesOf<Material>::type, DeckName);

/// One update from a fresh state (or from `state0`) at H: S, W, dissipated.
template <class M>
double stress_at(const M& m, const double H[9], double S[9], double* dissipated = nullptr,
                 const double* state0 = nullptr) {
  double state[max_state > 0 ? max_state : 1] = {};
  if (state0) std::copy(state0, state0 + M::state_size, state);
  double d = 0.0;
  const double W = point_stress(m, H, state, 1e-15, S, d);
  if (dissipated) *dissipated = d;
  return W;
}

double max_abs(const double* a, int n) {
  double x = 0.0;
  for (int k = 0; k < n; ++k) x = std::max(x, std::abs(a[k]));
  return x;
}

/// The amplitudes of H each test runs at: small for all; finite where the model takes them (finite
/// strain or stateless: a stateful small-strain model leaves its elastic range there).
template <class M>
std::vector<double> amplitudes() {
  if (M::finite_strain || M::state_size == 0) return {1e-3, 0.1, 0.3};
  return {1e-3};
}

TYPED_TEST(EveryModel, ZeroStressAndEnergyAtTheIdentity) {
  using M = TypeParam;
  const M m = make_model<M>();
  const double H[9] = {};
  double S[9], d = -1.0;
  const double W = stress_at(m, H, S, &d);
  for (int k = 0; k < 9; ++k) EXPECT_LE(std::abs(S[k]), 1e-12 * m.mu) << k;
  EXPECT_LE(std::abs(W), 1e-20 * m.mu);
  EXPECT_EQ(d, 0.0);
  double state[max_state > 0 ? max_state : 1] = {}, voigt[6];
  point_cauchy_stress(m, H, state, voigt);
  for (int k = 0; k < 6; ++k) EXPECT_LE(std::abs(voigt[k]), 1e-12 * m.mu) << k;
}

TYPED_TEST(EveryModel, StressIsTheGradientOfTheEnergy) {
  using M = TypeParam;
  const M m = make_model<M>();
  for (double a : amplitudes<M>()) {
    const auto H = gradient(a);
    double S[9], d = 0.0;
    stress_at(m, H.data(), S, &d);
    ASSERT_EQ(d, 0.0) << "the point at amplitude " << a << " is not elastic: the declared keys' values "
                      << "(every_model_support.hpp) put it past the model's elastic range";
    // Central difference with step h = 1e-5: the truncation h^2 W'''/6 (W''' of order lambda + 2 mu =
    // 1.3e11 Pa here) and the round-off eps (lambda + 2 mu) / h (W's terms are of that order, e.g.
    // mu I1 / 2, whatever H) are each a few Pa; the tolerance, 1e-6 of max|S|, is 46 Pa or more.
    const double h = 1e-5, tol = 1e-6 * max_abs(S, 9);
    for (int k = 0; k < 9; ++k) {
      auto Hp = H, Hm = H;
      Hp[k] += h;
      Hm[k] -= h;
      double Sp[9], Sm[9];
      const double dW = (stress_at(m, Hp.data(), Sp) - stress_at(m, Hm.data(), Sm)) / (2.0 * h);
      EXPECT_NEAR(S[k], dW, tol) << "amplitude " << a << ", component " << k;
    }
    // The Cauchy stress for output: S itself (small strain), P F^T / J (finite strain).
    double state[max_state > 0 ? max_state : 1] = {}, Sd[9], dd, voigt[6];
    point_stress(m, H.data(), state, 1e-15, Sd, dd);
    point_cauchy_stress(m, H.data(), state, voigt);
    double sigma[9];
    const double F[9] = {1 + H[0], H[1], H[2], H[3], 1 + H[4], H[5], H[6], H[7], 1 + H[8]};
    double C[9];
    const double J = cofactor3(F, C);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double x = 0.0;
        for (int K = 0; K < 3; ++K) x += S[3 * i + K] * F[3 * j + K];
        sigma[3 * i + j] = M::finite_strain ? x / J : S[3 * i + j];
      }
    const int voigt_index[6] = {0, 4, 8, 1, 5, 2};
    for (int v = 0; v < 6; ++v) EXPECT_NEAR(voigt[v], sigma[voigt_index[v]], 1e-12 * max_abs(sigma, 9)) << v;
  }
}

TYPED_TEST(EveryModel, FiniteStrainIsObjective) {
  using M = TypeParam;
  if constexpr (!M::finite_strain) {
    GTEST_SKIP() << "small strain (finite_strain = false)";
  } else {
    const M m = make_model<M>();
    const double c = std::cos(0.7), s = std::sin(0.7);
    const double Q[9] = {c, -s, 0, s, c, 0, 0, 0, 1};  // 0.7 rad about z
    for (double a : amplitudes<M>()) {
      const auto H = gradient(a, 1);
      const double F[9] = {1 + H[0], H[1], H[2], H[3], 1 + H[4], H[5], H[6], H[7], 1 + H[8]};
      double HQ[9];
      for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J) {
          double x = 0.0;
          for (int k = 0; k < 3; ++k) x += Q[3 * i + k] * F[3 * k + J];
          HQ[3 * i + J] = x - (i == J ? 1.0 : 0.0);
        }
      double P[9], PQ[9];
      const double W = stress_at(m, H.data(), P), WQ = stress_at(m, HQ, PQ);
      EXPECT_NEAR(WQ, W, 1e-12 * std::abs(W) + 1e-9 * m.mu * a * a);
      for (int i = 0; i < 3; ++i)
        for (int J = 0; J < 3; ++J) {
          double x = 0.0;
          for (int k = 0; k < 3; ++k) x += Q[3 * i + k] * P[3 * k + J];
          EXPECT_NEAR(PQ[3 * i + J], x, 1e-12 * max_abs(P, 9)) << i << J;
        }
    }
  }
}

/// The run at width `width` against the lone points, bitwise (memcmp: NaN and -0 included).
template <class M>
void expect_lanes_bitwise(const std::vector<double>& lone, const std::vector<double>& wide, int lanes, int width) {
  const std::vector<double> grouped = by_point(wide, lanes, width, values_per_point<M>());
  ASSERT_EQ(grouped.size(), lone.size());
  for (std::size_t i = 0; i < lone.size(); ++i)
    EXPECT_EQ(std::memcmp(&grouped[i], &lone[i], sizeof(double)), 0)
        << "width " << width << ": value " << i << " (point " << i / (2 * values_per_point<M>()) << ") "
        << grouped[i] << " alone " << lone[i];
}

TYPED_TEST(EveryModel, LanesAreBitwiseTheLonePoints) {
  using M = TypeParam;
  const M m = make_model<M>();
  const Material as_variant = m;
  std::vector<double> lone(values_per_run<M>(max_lanes)), wide(lone.size());
  run_at_width<double>(m, max_lanes, lone.data());
  run_at_width<double2>(m, max_lanes, wide.data());
  expect_lanes_bitwise<M>(lone, wide, max_lanes, 2);
  if (__builtin_cpu_supports("avx2") && run_four_lanes(as_variant, max_lanes, wide.data()))
    expect_lanes_bitwise<M>(lone, wide, max_lanes, 4);
  else
    GTEST_LOG_(INFO) << "four lanes not run (no AVX2 build or CPU)";
  if (__builtin_cpu_supports("avx512f") && run_eight_lanes(as_variant, max_lanes, wide.data()))
    expect_lanes_bitwise<M>(lone, wide, max_lanes, 8);
  else
    GTEST_LOG_(INFO) << "eight lanes not run (no AVX-512 build or CPU)";
}

/// max over unit n of n_i n_j c_ijkl n_k n_l (c [81], row-major ijkl): the best of 2000 directions
/// on a Fibonacci sphere (about 0.05 rad apart), then a pattern search around it, tilting n by s
/// toward +-t1, +-t2 (t1, t2 perpendicular to n) and halving s from 0.05 rad to 1e-9 rad when no tilt
/// gains: the form is smooth, so its maximum is found to (1e-9)^2 relative.
double longitudinal_max(const double c[81]) {
  auto form = [&](const double n[3]) {
    double f = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) f += c[27 * i + 9 * j + 3 * k + l] * n[i] * n[j] * n[k] * n[l];
    return f;
  };
  double best[3] = {0, 0, 1}, fbest = -INFINITY;
  const int count = 2000;
  for (int p = 0; p < count; ++p) {
    const double z = 1.0 - (2.0 * p + 1.0) / count, r = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * p;
    const double n[3] = {r * std::cos(phi), r * std::sin(phi), z};
    if (const double f = form(n); f > fbest) fbest = f, std::copy(n, n + 3, best);
  }
  for (double s = 0.05; s > 1e-9;) {
    // t1, t2: an orthonormal pair perpendicular to best
    const double a[3] = {std::abs(best[0]) < 0.9 ? 1.0 : 0.0, std::abs(best[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    double t1[3] = {best[1] * a[2] - best[2] * a[1], best[2] * a[0] - best[0] * a[2], best[0] * a[1] - best[1] * a[0]};
    const double n1 = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1] + t1[2] * t1[2]);
    for (double& x : t1) x /= n1;
    const double t2[3] = {best[1] * t1[2] - best[2] * t1[1], best[2] * t1[0] - best[0] * t1[2], best[0] * t1[1] - best[1] * t1[0]};
    bool gained = false;
    for (const double* t : {static_cast<const double*>(t1), t2})
      for (double sign : {1.0, -1.0}) {
        double n[3];
        for (int i = 0; i < 3; ++i) n[i] = best[i] + sign * s * t[i];
        const double norm = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& x : n) x /= norm;
        if (const double f = form(n); f > fbest) fbest = f, std::copy(n, n + 3, best), gained = true;
      }
    if (!gained) s *= 0.5;
  }
  return fbest;
}

/// The tangent c of the rule above at H (state: the point's state at H), by central differences of
/// the stress with step h.
template <class M>
void spatial_tangent(const M& m, const double H[9], const double* state, double c[81]) {
  const double h = 1e-6;
  double A[81];  // dS_iJ / dH_kL
  for (int kl = 0; kl < 9; ++kl) {
    double Hp[9], Hm[9], Sp[9], Sm[9];
    std::copy(H, H + 9, Hp);
    std::copy(H, H + 9, Hm);
    Hp[kl] += h;
    Hm[kl] -= h;
    stress_at(m, Hp, Sp, nullptr, state);
    stress_at(m, Hm, Sm, nullptr, state);
    for (int iJ = 0; iJ < 9; ++iJ) A[9 * iJ + kl] = (Sp[iJ] - Sm[iJ]) / (2.0 * h);
  }
  if constexpr (!M::finite_strain) {
    std::copy(A, A + 81, c);
  } else {
    const double F[9] = {1 + H[0], H[1], H[2], H[3], 1 + H[4], H[5], H[6], H[7], 1 + H[8]};
    double C[9], P[9];
    const double J = cofactor3(F, C);
    stress_at(m, H, P, nullptr, state);
    double sigma[9];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double x = 0.0;
        for (int K = 0; K < 3; ++K) x += P[3 * i + K] * F[3 * j + K];
        sigma[3 * i + j] = x / J;
      }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) {
            double x = 0.0;
            for (int JJ = 0; JJ < 3; ++JJ)
              for (int L = 0; L < 3; ++L) x += F[3 * j + JJ] * F[3 * l + L] * A[9 * (3 * i + JJ) + 3 * k + L];
            c[27 * i + 9 * j + 3 * k + l] = x / J - (i == k ? sigma[3 * j + l] : 0.0);
          }
  }
}

TYPED_TEST(EveryModel, WaveModulusIsThePWaveModulusOfTheTangent) {
  using M = TypeParam;
  const M m = make_model<M>();
  double c[81];
  const double zero[9] = {};
  spatial_tangent(m, zero, nullptr, c);
  EXPECT_NEAR(m.wave_modulus(nullptr), longitudinal_max(c), 1e-6 * m.wave_modulus(nullptr)) << "reference (H null)";
  for (double a : amplitudes<M>()) {
    const auto H = gradient(a, 2);
    spatial_tangent(m, H.data(), nullptr, c);
    EXPECT_NEAR(m.wave_modulus(H.data()), longitudinal_max(c), 1e-6 * m.wave_modulus(H.data())) << "amplitude " << a;
  }
  if constexpr (M::state_size > 0) {
    // Flowing: the state at H from a first update, the tangent around it includes the return.
    const auto H = gradient(0.05, 2);
    double state[max_state] = {}, S[9], d = 0.0;
    point_stress(m, H.data(), state, 1e-15, S, d);
    spatial_tangent(m, H.data(), state, c);
    EXPECT_GE(m.wave_modulus(H.data()), (1.0 - 1e-6) * longitudinal_max(c)) << "past the elastic range";
  }
}

TYPED_TEST(EveryModel, DeclaredKeysBuildTheModelThroughTheList) {
  using M = TypeParam;
  const int index = model_index(M::deck_name);
  ASSERT_GE(index, 0);
  EXPECT_EQ(model_keys(index).size(), M::keys.size());
  for (const KeyDecl& k : M::keys) {
    EXPECT_FALSE(k.key.empty());
    EXPECT_FALSE(k.help.empty()) << k.key;
    EXPECT_TRUE(k.required || !k.default_text.empty())
        << k.key << ": a model reads every key by name (KeyValues::at): declare it required or give a default";
  }
  const Material made = make_material(index, youngs, poisson, density, values_from_declarations(M::keys));
  ASSERT_TRUE(std::holds_alternative<M>(made));
  EXPECT_EQ(model_name(made), M::deck_name);
  EXPECT_EQ(density_of(made), density);
  EXPECT_EQ(state_size_of(made), M::state_size);
}

}  // namespace
}  // namespace tribex::materials
