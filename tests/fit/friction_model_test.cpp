// SPDX-License-Identifier: MIT
// Contact-area laws of the friction fit against closed forms: DMT and JKR numbers of docs/theory.md
// 8.2-8.5, the coated law's two limits (11.1), COS at alpha = 0 against DMT, the JKR compressive
// load against direct quadrature, and the coating table.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "tools/common/errors.hpp"
#include "tools/fit/friction_model.hpp"

namespace tribex::fit {
namespace {

constexpr double pi = std::numbers::pi;

FrictionSetup si_uncoated(AreaModel m) {
  FrictionSetup s;
  s.model = m;
  s.radius = 27e-9;
  s.reduced_modulus = 84.1e9;  // docs/theory.md 8.5: Si on Si, E = 160 GPa, nu = 0.22
  return s;
}

TEST(FrictionModel, DmtRadiiOfPhysicsMd85) {
  const FrictionModel m(si_uncoated(AreaModel::dmt));
  const FrictionParams p = m.defaults(1.0, 0.05);
  // a = 1.645 nm at 10 nN, 1.269 nm at zero load (quoted to 4 digits).
  EXPECT_NEAR(std::sqrt(m.contact(p, 10e-9)->area / pi), 1.645e-9, 0.001e-9);
  EXPECT_NEAR(std::sqrt(m.contact(p, 0.0)->area / pi), 1.269e-9, 0.001e-9);
  EXPECT_NEAR(m.pull_off_load(p), -2 * pi * 0.05 * 27e-9, 1e-20);  // 8.48 nN
  EXPECT_FALSE(m.contact(p, -8.5e-9).has_value());                 // below pull-off
  EXPECT_NEAR(m.contact(p, 10e-9)->carried_load, 10e-9 + 2 * pi * 0.05 * 27e-9, 1e-20);
}

TEST(FrictionModel, JkrZeroLoadRadiusAndCompressiveLoadByQuadrature) {
  const FrictionModel m(si_uncoated(AreaModel::jkr));
  const FrictionParams p = m.defaults(1.0, 0.05);
  const double e = 84.1e9, r = 27e-9, w = 0.05;
  const double a0 = std::cbrt(9 * pi * w * r * r / (2 * e));  // docs/theory.md 8.3
  EXPECT_NEAR(std::sqrt(m.contact(p, 0.0)->area / pi), a0, 1e-9 * a0);
  EXPECT_NEAR(m.pull_off_load(p), -1.5 * pi * w * r, 1e-20);
  for (double load : {-5e-9, 0.0, 20e-9}) {
    const auto c = *m.contact(p, load);
    const double a = std::sqrt(c.area / pi);
    // int_0^a max(p, 0) 2 pi r dr by the midpoint rule in theta, r = a sin(theta), which removes
    // the edge singularity: p dA = 2 pi a^2 (p0 cos^2 - p1) sin(theta) d theta.
    const double p0 = 2 * a * e / (pi * r), p1 = std::sqrt(2 * w * e / (pi * a));
    const int n = 200000;
    double sum = 0, net = 0;
    for (int i = 0; i < n; ++i) {
      const double th = (i + 0.5) / n * pi / 2, d = pi / 2 / n;
      const double pr = p0 * std::cos(th) - p1 / std::cos(th);
      const double da = 2 * pi * a * a * std::sin(th) * std::cos(th) * d;
      sum += std::max(pr, 0.0) * da;
      net += pr * da;
    }
    EXPECT_NEAR(c.carried_load, sum, 1e-3 * sum) << load;
    EXPECT_GE(c.carried_load, load);  // clipping the tension only adds
    EXPECT_NEAR(net, load, 1e-6 * (std::abs(load) + 1e-9));  // the net JKR pressure integrates to L
  }
}

TEST(FrictionModel, CosAtAlphaZeroIsDmt) {
  FrictionSetup cs = si_uncoated(AreaModel::cos);
  cs.cos_alpha = 0.0;
  const FrictionModel cos(cs), dmt(si_uncoated(AreaModel::dmt));
  const FrictionParams p = cos.defaults(1.0, 0.05);
  EXPECT_NEAR(cos.pull_off_load(p), dmt.pull_off_load(p), 1e-12 * std::abs(dmt.pull_off_load(p)));
  for (double load : {-8e-9, 0.0, 10e-9, 30e-9})  // Pietrement-Troyon a0(0) = 1.261 vs 2^(1/3) = 1.2599
    EXPECT_NEAR(cos.contact(p, load)->area / dmt.contact(p, load)->area, 1.0, 2e-3) << load;
}

FrictionSetup coated(double a_fit, double b) {
  FrictionSetup s;
  s.model = AreaModel::coated;
  s.area_law = AreaLawConstants{a_fit, b, 0, 0};
  return s;
}

TEST(FrictionModel, CoatedLawLimits) {
  // f = 1: Hertz against a half-space of coating, 1/E* = 1/Ebar + 1/Ebar_c (docs/theory.md 11.1).
  const FrictionModel shallow(coated(1.0, 0.0));
  const FrictionParams p = shallow.defaults(1.0, 0.05);
  const double ebar = 161e9 / (1 - 0.23 * 0.23), ebar_c = 8e9 / (1 - 0.16);
  const double e_star = 1 / (1 / ebar + 1 / ebar_c), r = 27e-9;
  const double load = 10e-9, eff = load + 2 * pi * 0.05 * r;
  EXPECT_NEAR(shallow.contact(p, load)->area, pi * std::pow(3 * eff * r / (4 * e_star), 2.0 / 3), 1e-12 * 1e-17);
  // f clipped at 1 from above.
  EXPECT_NEAR(FrictionModel(coated(5.0, 0.0)).contact(p, load)->area, shallow.contact(p, load)->area, 1e-30);
  // f clipped at f_deep from below: Si-Si Hertz, 1/E* = 2/Ebar.
  const double deep = FrictionModel(coated(1e-6, 0.0)).contact(p, load)->area;
  EXPECT_NEAR(deep, pi * std::pow(3 * eff * r / (4 * ebar / 2), 2.0 / 3), 1e-9 * deep);
  // In between: the power law A (P/(Ebar_c h_c^2))^b.
  const double mid = FrictionModel(coated(0.6, -0.1)).contact(p, load)->area;
  const double f = 0.6 * std::pow(eff / (ebar_c * 4e-18), -0.1);
  ASSERT_LT(f, 1.0);
  EXPECT_NEAR(mid, shallow.contact(p, load)->area * f, 1e-9 * mid);
}

std::string write_temp(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_fit_model_test";
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

TEST(CoatingTable, InterpolatesInLogRatioAndRefusesOutside) {
  const auto path = write_temp("table.csv", "ebar_c_over_ebar,A,b,A_sigma\n0.028,1.0,-0.1,0.02\n0.056,2.0,-0.2,0.04\n");
  const auto t = CoatingTable::read(path);
  const auto mid = t.at(std::sqrt(0.028 * 0.056));  // halfway in ln
  EXPECT_NEAR(mid.A, 1.5, 1e-12);
  EXPECT_NEAR(mid.b, -0.15, 1e-12);
  EXPECT_NEAR(mid.A_sigma, 0.03, 1e-12);
  EXPECT_NEAR(t.at(0.056).A, 2.0, 1e-12);
  EXPECT_THROW(t.at(0.06), tools::BadInput);
  try {
    CoatingTable::read(write_temp("missing_ratio.csv", "A,b\n1,0\n"));
    ADD_FAILURE() << "no error";
  } catch (const tools::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("missing_ratio.csv:1: missing column 'ebar_c_over_ebar'"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(CoatingTable::read(write_temp("decreasing.csv", "ebar_c_over_ebar,A,b\n0.05,1,0\n0.02,1,0\n")),
               tools::BadInput);
  try {
    CoatingTable::read("/nonexistent/results.csv");
    ADD_FAILURE() << "no error";
  } catch (const tools::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("--coating-table"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribex::fit
