// SPDX-License-Identifier: MIT
// The regime each `tribex fit` model assumes and the Tabor parameter of the fit (tools/fit/regime.hpp;
// docs/theory.md 8.5, 9): the Si numbers of 8.5, the DMT and JKR warnings, coated with the coating's E*,
// md and cos without a regime.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tools/fit/regime.hpp"

namespace tribex::fit {
namespace {

FrictionSetup si(AreaModel m) {
  FrictionSetup s;
  s.model = m;
  s.radius = 27e-9;  // E = 161 GPa, nu = 0.23: E* = 85.0 GPa
  if (m == AreaModel::coated) s.area_law = AreaLawConstants{0.7, -0.09, 0, 0};
  return s;
}

FrictionParams with_work(const FrictionModel& m, double w) {
  FrictionParams p = m.defaults(1e8, w);
  p.work_of_adhesion = w;
  return p;
}

TEST(FitRegime, DmtOnSiliconIsInsideAndItsTaborParameterIsThatOf85) {
  const FrictionModel m(si(AreaModel::dmt));
  const auto c = check_regime(m, with_work(m, 0.05));
  ASSERT_TRUE(c.regime.has_value());
  EXPECT_EQ(*c.regime, tools::AdhesionRegime::dmt);
  EXPECT_NEAR(c.tabor, 0.0702, 0.0005);  // docs/theory.md 8.5: 0.070 at z0 = 0.3 nm
  EXPECT_TRUE(c.warning.empty()) << c.warning;
}

TEST(FitRegime, DmtWithALargeWorkWarnsInOneLine) {
  const FrictionModel m(si(AreaModel::dmt));
  const auto c = check_regime(m, with_work(m, 1.0));  // mu_T = 0.0702 * 20^(2/3) = 0.517
  EXPECT_NEAR(c.tabor, 0.0702 * std::pow(20.0, 2.0 / 3.0), 0.002);
  EXPECT_NE(c.warning.find("assumes DMT (mu_T <= 0.3) but mu_T = 0.517"), std::string::npos) << c.warning;
  EXPECT_EQ(std::count(c.warning.begin(), c.warning.end(), '\n'), 0);
}

TEST(FitRegime, JkrOnSiliconWarns) {
  const FrictionModel m(si(AreaModel::jkr));
  const auto c = check_regime(m, with_work(m, 0.05));
  EXPECT_NE(c.warning.find("assumes JKR (mu_T >= 3) but mu_T = 0.0702"), std::string::npos) << c.warning;
}

TEST(FitRegime, CoatedUsesTheCoatingModulusAndWarnsAtTheStudysSecondWork) {
  FrictionSetup s = si(AreaModel::coated);
  const FrictionModel m(s);
  FrictionParams p = with_work(m, 0.10);
  p.coating_youngs = 8e9;
  const auto c = check_regime(m, p);
  // 1/E* = (1 - 0.23^2)/161 GPa + (1 - 0.4^2)/8 GPa: E* = 9.02 GPa; mu_T = 0.497 (W = 0.05: 0.313).
  EXPECT_NEAR(c.e_star, 9.02e9, 0.01e9);
  EXPECT_NEAR(c.tabor, 0.497, 0.002);
  EXPECT_NE(c.warning.find("Eq. 3.1 has no transition form"), std::string::npos) << c.warning;
}

TEST(FitRegime, TransitionModelsAssumeNoRegime) {
  FrictionSetup s = si(AreaModel::maugis_dugdale);
  s.md_lambda = 1.157;
  const FrictionModel md(s);
  const auto c = check_regime(md, with_work(md, 0.05));
  EXPECT_FALSE(c.regime.has_value());
  EXPECT_NEAR(c.tabor, 1.0, 1e-12);
  EXPECT_TRUE(c.warning.empty());
  const FrictionModel cos(si(AreaModel::cos));
  EXPECT_FALSE(check_regime(cos, with_work(cos, 0.05)).regime.has_value());
}

}  // namespace
}  // namespace tribex::fit
