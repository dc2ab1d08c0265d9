// SPDX-License-Identifier: MIT
// tools/common/tabor.hpp: the Tabor parameter (docs/theory.md 8.5) and the regime warnings' limits.
#include <gtest/gtest.h>

#include <algorithm>

#include "tools/common/tabor.hpp"

namespace tribex::tools {
namespace {

TEST(Tabor, SiliconOfTheory85) {
  // R 27 nm, W 0.05 J/m^2, E* = 85.0 GPa: 0.105 / 0.084 / 0.070 at z0 = 0.2 / 0.25 / 0.3 nm.
  const double e_star = 161e9 / (2 * (1 - 0.23 * 0.23));
  EXPECT_NEAR(tabor_parameter(27e-9, 0.05, e_star, 0.2e-9), 0.105, 0.0005);
  EXPECT_NEAR(tabor_parameter(27e-9, 0.05, e_star, 0.25e-9), 0.084, 0.0005);
  EXPECT_NEAR(tabor_parameter(27e-9, 0.05, e_star, 0.3e-9), 0.070, 0.0005);
}

TEST(Tabor, WarningsOutsideTheAssumedEndOnly) {
  EXPECT_EQ(regime_warning(AdhesionRegime::dmt, 0.3, "x", "y", "z"), "");
  EXPECT_EQ(regime_warning(AdhesionRegime::jkr, 3.0, "x", "y", "z"), "");
  const auto d = regime_warning(AdhesionRegime::dmt, 0.31, "tool", "inputs", "advice");
  EXPECT_EQ(d.rfind("warning: tool assumes DMT (mu_T <= 0.3) but mu_T = 0.31 (inputs)", 0), 0u) << d;
  EXPECT_NE(d.find("; advice"), std::string::npos);
  EXPECT_EQ(std::count(d.begin(), d.end(), '\n'), 0);
  const auto j = regime_warning(AdhesionRegime::jkr, 2.9, "tool", "inputs", "advice");
  EXPECT_NE(j.find("assumes JKR (mu_T >= 3) but mu_T = 2.9"), std::string::npos) << j;
}

}  // namespace
}  // namespace tribex::tools
