// SPDX-License-Identifier: MIT
// Acceptance of `tribex fit friction` (issue 7): tau* and W recovered from synthetic data made
// with known values and 5 % noise, for several parameter sets and every area model; the
// reported sigmas are checked for calibration by Monte Carlo (about 68 % of fits within 1 sigma),
// so the per-set 2-sigma bounds below are meaningful rather than loose. Plus the DMT
// verification handle of docs/theory.md 9.3 and the tau/Ec^(2/3) non-identifiability of report 3.3.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "tools/fit/friction_fit.hpp"

namespace tribex::fit {
namespace {

constexpr double pi = std::numbers::pi;

// A synthetic A, b table in the spirit of the report's Table B.1 (its values are withheld): A
// rises and b falls modestly with Ebar_c/Ebar. Not FE results: only the fit machinery is tested.
CoatingTable synthetic_table() {
  return CoatingTable("synthetic", {0.014, 0.028, 0.056, 0.112, 0.2},
                      {{0.70, -0.10, 0, 0}, {0.72, -0.12, 0, 0}, {0.75, -0.15, 0, 0}, {0.78, -0.17, 0, 0},
                       {0.80, -0.18, 0, 0}});
}

struct Case {
  double radius, coating_youngs, tau, w;
};

FrictionSetup coated_setup(const Case& c) {
  FrictionSetup s;
  s.model = AreaModel::coated;
  s.radius = c.radius;
  s.coating_youngs = c.coating_youngs;
  s.table = synthetic_table();
  return s;
}

// Loads from 80 % of the way to pull-off up to 40 nN, as in an AFM ramp.
std::vector<double> ramp_for(const FrictionModel& m, const FrictionParams& p, int n = 30) {
  return load_ramp(0.8 * m.pull_off_load(p), 40e-9, n);
}

// One parameter set is "recovered within the reported uncertainties" when, over 5 independent
// noise draws, the rms of the z-scores (fit - truth)/sigma of tau and of W is below 2 (its expected
// value is 1; rms^2 ~ chi^2_5/5 exceeds 4 with probability 1e-3) and no single draw is off by
// 4 sigma. A single draw at a 2- or 3-sigma bound fails by chance: the first version of this test
// met a 3.08-sigma draw (md, lambda 0.5). The calibration of sigma itself is the coverage test.
void expect_recovered(const FrictionModel& m, const FrictionParams& truth, const std::vector<double>& load,
                      Residual kind, std::uint64_t seed, const std::string& what) {
  double z2_tau = 0, z2_w = 0;
  const int draws = 5;
  for (int k = 0; k < draws; ++k) {
    const auto f = synth_friction(m, truth, load, 0.05, kind, seed + static_cast<std::uint64_t>(k));
    const FrictionFit fit = fit_friction(m, load, f, kind);
    const double s_tau = fit.sigma(fit.names[0]), s_w = fit.sigma("W");
    const double z_tau = (fit.best.tau - truth.tau) / s_tau;
    const double z_w = (fit.best.work_of_adhesion - truth.work_of_adhesion) / s_w;
    EXPECT_LT(std::abs(z_tau), 4.0) << what << ": tau " << fit.best.tau << " +- " << s_tau;
    EXPECT_LT(std::abs(z_w), 4.0) << what << ": W " << fit.best.work_of_adhesion << " +- " << s_w;
    // The sigmas must be informative: 5 % noise on 30 points cannot justify more than 10 % / 25 %.
    EXPECT_LT(s_tau, 0.10 * truth.tau) << what;
    EXPECT_LT(s_w, 0.25 * truth.work_of_adhesion) << what;
    EXPECT_TRUE(fit.lm.converged) << what;
    z2_tau += z_tau * z_tau / draws;
    z2_w += z_w * z_w / draws;
  }
  EXPECT_LT(std::sqrt(z2_tau), 2.0) << what;
  EXPECT_LT(std::sqrt(z2_w), 2.0) << what;
}

TEST(FrictionFit, CoatedRecoversTauAndWFromFivePercentNoise) {
  const Case cases[] = {{27e-9, 8e9, 194e6, 0.05}, {30e-9, 4e9, 100e6, 0.03}, {35e-9, 16e9, 300e6, 0.08},
                        {27e-9, 2e9, 60e6, 0.10}};
  std::uint64_t seed = 11;
  for (const auto& c : cases) {
    const FrictionModel m(coated_setup(c));
    const FrictionParams truth = m.defaults(c.tau, c.w);
    const auto load = ramp_for(m, truth);
    for (Residual kind : {Residual::relative, Residual::absolute}) {
      expect_recovered(m, truth, load, kind, seed,
                       "Ec " + std::to_string(c.coating_youngs) + (kind == Residual::relative ? " rel" : " abs"));
      seed += 5;
    }
  }
}

// The same acceptance with A, b interpolated from the coated-substrate FE study's own table
// (verification/coated/results.csv, written by verification/coated/study.py), at three coating
// moduli inside its range of Ebar_c/Ebar (0.014 .. 0.112): tau* and W recovered within their sigmas.
TEST(FrictionFit, CoatedRecoversTauAndWWithTheStudysTable) {
  const CoatingTable table = CoatingTable::read(TRIBEX_SOURCE_DIR "/verification/coated/results.csv");
  const Case cases[] = {{27e-9, 8e9, 194e6, 0.05}, {27e-9, 3e9, 80e6, 0.03}, {27e-9, 14e9, 250e6, 0.08}};
  std::uint64_t seed = 301;
  for (const auto& c : cases) {
    FrictionSetup s = coated_setup(c);
    s.table = table;
    const FrictionModel m(s);
    const FrictionParams truth = m.defaults(c.tau, c.w);
    expect_recovered(m, truth, ramp_for(m, truth), Residual::relative, seed,
                     "study table, Ec " + std::to_string(c.coating_youngs));
    seed += 5;
  }
}

// The sigmas are honest: over 200 noise draws, tau and W each land within 1 sigma of the truth
// in 68 % +- 10 % of fits (3 binomial standard deviations: sqrt(0.68 0.32/200) = 3.3 %).
TEST(FrictionFit, ReportedSigmasHaveOneSigmaCoverage) {
  const Case c{27e-9, 8e9, 194e6, 0.05};
  const FrictionModel m(coated_setup(c));
  const FrictionParams truth = m.defaults(c.tau, c.w);
  const auto load = ramp_for(m, truth);
  int in_tau = 0, in_w = 0;
  const int n = 200;
  for (int k = 0; k < n; ++k) {
    const auto f = synth_friction(m, truth, load, 0.05, Residual::relative, 1000 + static_cast<std::uint64_t>(k));
    const FrictionFit fit = fit_friction(m, load, f, Residual::relative);
    in_tau += std::abs(fit.best.tau - c.tau) < fit.sigma("tau");
    in_w += std::abs(fit.best.work_of_adhesion - c.w) < fit.sigma("W");
  }
  EXPECT_NEAR(in_tau / double(n), 0.68, 0.10);
  EXPECT_NEAR(in_w / double(n), 0.68, 0.10);
}

FrictionSetup uncoated(AreaModel model) {
  FrictionSetup s;
  s.model = model;
  s.radius = 27e-9;
  s.reduced_modulus = 84.1e9;
  return s;
}

TEST(FrictionFit, UncoatedModelsRecoverTauAndW) {
  FrictionSetup md_lambda = uncoated(AreaModel::maugis_dugdale);
  md_lambda.md_lambda = 0.5;
  FrictionSetup md_z0 = uncoated(AreaModel::maugis_dugdale);
  md_z0.md_z0 = 0.2e-9;  // lambda ~ 0.12 at W = 0.05 (docs/theory.md 8.5)
  FrictionSetup cos_free = uncoated(AreaModel::cos);
  FrictionSetup cos_fixed = uncoated(AreaModel::cos);
  cos_fixed.cos_alpha = 0.5;
  const std::pair<FrictionSetup, std::string> setups[] = {{uncoated(AreaModel::dmt), "dmt"},
                                                          {uncoated(AreaModel::jkr), "jkr"},
                                                          {md_lambda, "md lambda 0.5"},
                                                          {md_z0, "md z0"},
                                                          {cos_fixed, "cos alpha 0.5"}};
  std::uint64_t seed = 7;
  for (const auto& [s, what] : setups) {
    const FrictionModel m(s);
    const FrictionParams truth = m.defaults(120e6, 0.06);
    expect_recovered(m, truth, ramp_for(m, truth), Residual::relative, seed, what);
    seed += 5;
  }
  // COS with alpha free: three parameters, alpha recovered too.
  const FrictionModel m(cos_free);
  FrictionParams truth = m.defaults(120e6, 0.06);
  truth.cos_alpha = 0.6;
  const auto load = ramp_for(m, truth, 40);
  expect_recovered(m, truth, load, Residual::relative, 99, "cos free alpha");
  const FrictionFit fit = fit_friction(m, load, synth_friction(m, truth, load, 0.05, Residual::relative, 99),
                                       Residual::relative);
  EXPECT_LT(std::abs(fit.best.cos_alpha - 0.6), 3 * fit.sigma("cos_alpha"));
}

TEST(FrictionFit, PressureDependentShearStrength) {
  FrictionSetup s = uncoated(AreaModel::dmt);
  s.pressure_dependent = true;
  const FrictionModel m(s);
  FrictionParams truth = m.defaults(50e6, 0.04);
  truth.pressure_coefficient = 0.15;  // tau = tau0 + alpha_p p (report Eq. C.2)
  const auto load = ramp_for(m, truth, 40);
  const auto f = synth_friction(m, truth, load, 0.05, Residual::relative, 5);
  const FrictionFit fit = fit_friction(m, load, f, Residual::relative);
  ASSERT_EQ(fit.names, (std::vector<std::string>{"tau0", "W", "alpha_p"}));
  EXPECT_LT(std::abs(fit.best.tau - 50e6), 3 * fit.sigma("tau0"));
  EXPECT_LT(std::abs(fit.best.work_of_adhesion - 0.04), 3 * fit.sigma("W"));
  EXPECT_LT(std::abs(fit.best.pressure_coefficient - 0.15), 3 * fit.sigma("alpha_p"));
  EXPECT_LT(fit.sigma("alpha_p"), 0.05);
}

// docs/theory.md 9.3: DMT data, R = 27 nm, E* = 84.1 GPa, W = 0.05 J/m^2, tau* = 100 MPa, L = -5..30 nN.
TEST(FrictionFit, DmtVerificationHandle) {
  const FrictionModel dmt(uncoated(AreaModel::dmt));
  const FrictionParams truth = dmt.defaults(100e6, 0.05);
  const auto load = load_ramp(-5e-9, 30e-9, 36);
  const auto f = synth_friction(dmt, truth, load, 0.0, Residual::absolute, 1);
  const ShortcutFit sc = dmt_shortcut(load, f, 27e-9, 84.1e9);
  EXPECT_NEAR(sc.work_of_adhesion / 0.05, 1.0, 1e-6);
  EXPECT_NEAR(sc.tau / 100e6, 1.0, 1e-6);
  const FrictionFit full = fit_friction(dmt, load, f);
  EXPECT_NEAR(full.best.work_of_adhesion / 0.05, 1.0, 1e-6);
  EXPECT_NEAR(full.best.tau / 100e6, 1.0, 1e-6);
  const FrictionFit cos = fit_friction(FrictionModel(uncoated(AreaModel::cos)), load, f);
  EXPECT_LT(cos.best.cos_alpha, 0.15);
  EXPECT_NEAR(cos.best.work_of_adhesion / 0.05, 1.0, 0.03);
  EXPECT_NEAR(cos.best.tau / 100e6, 1.0, 0.03);
}

// Report 3.3: with Ec free, Eq. 3.1 fixes only tau*/Ec^(2/3). The fit must say so through the
// correlation and the far smaller sigma of the combination, not by hiding Ec.
TEST(FrictionFit, CoatingModulusFreeShowsNonIdentifiability) {
  const Case c{27e-9, 8e9, 194e6, 0.05};
  FrictionSetup s = coated_setup(c);
  s.free_coating_modulus = true;
  s.coating_youngs = 6e9;  // a wrong starting guess
  const FrictionModel m(s);
  FrictionParams truth = m.defaults(c.tau, c.w);
  truth.coating_youngs = c.coating_youngs;
  const auto load = ramp_for(m, truth);
  const auto f = synth_friction(m, truth, load, 0.05, Residual::relative, 3);
  const FrictionFit fit = fit_friction(m, load, f, Residual::relative);
  EXPECT_GT(std::abs(fit.correlation("tau", "Ec")), 0.95);
  const double rel_tau = fit.sigma("tau") / fit.best.tau;
  // The report's combination tau/Ec^(2/3) ...
  const Combination g = tau_over_ec_power(fit, 2.0 / 3.0);
  EXPECT_LT(std::abs(g.value - c.tau / std::pow(c.coating_youngs, 2.0 / 3.0)), 3 * g.sigma);
  EXPECT_LT(g.sigma / g.value, rel_tau);
  // ... and the valley's own exponent. At fixed tau, F ~ Ec^-k(L) with a local k(L) = -dlnF/dlnEc
  // that is 2/3 - 2/3 Ebar_c/(Ebar + Ebar_c) where f is clipped at 1 and moves with b and with the
  // table's A(Ec), b(Ec) elsewhere; the valley exponent must lie in the range of k(L) over the data.
  const Combination v = tau_over_ec_valley(fit);
  double k_lo = 1, k_hi = 0;
  for (double l : load) {
    FrictionParams up = truth;
    up.coating_youngs *= 1.001;
    const double k = -std::log((*m.friction(up, {l}))[0] / (*m.friction(truth, {l}))[0]) / std::log(1.001);
    k_lo = std::min(k_lo, k);
    k_hi = std::max(k_hi, k);
  }
  EXPECT_GT(v.exponent, k_lo - 0.02) << "k(L) in [" << k_lo << ", " << k_hi << "]";
  EXPECT_LT(v.exponent, k_hi + 0.02) << "k(L) in [" << k_lo << ", " << k_hi << "]";
  EXPECT_LT(k_hi - k_lo, 0.4);  // a narrow valley: one combination is fixed
  EXPECT_LT(std::abs(v.value - c.tau / std::pow(c.coating_youngs, v.exponent)), 3 * v.sigma);
  EXPECT_LT(v.sigma / v.value, rel_tau / 3);
  EXPECT_LT(std::abs(fit.best.work_of_adhesion - c.w), 3 * fit.sigma("W"));
}

}  // namespace
}  // namespace tribex::fit
