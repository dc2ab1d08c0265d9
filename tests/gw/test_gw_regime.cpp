// SPDX-License-Identifier: MIT
// The Tabor parameter of a DMT asperity in `tribex gw` units (tools/gw/gw_models.hpp asperity_tabor;
// docs/theory.md 10.4) against the dimensional definition (tools/common/tabor.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "tools/common/tabor.hpp"
#include "tools/gw/gw_models.hpp"

TEST(GwRegime, AsperityTaborParameterFromBetaAndZ0) {
  // R = 1 um, sigma_s = 3 nm, W = 0.05 J/m^2, E* = 85 GPa, z0 = 0.3 nm.
  const double r = 1e-6, sigma = 3e-9, w = 0.05, e_star = 85e9, z0 = 0.3e-9;
  const double beta = 3 * M_PI * w * std::sqrt(r) / (2 * e_star * std::pow(sigma, 1.5));
  const double mu = tribex::tools::tabor_parameter(r, w, e_star, z0);
  EXPECT_NEAR(tribex::gw::asperity_tabor(beta, z0 / sigma), mu, 1e-12 * mu);
  EXPECT_NEAR(mu, 0.2340, 0.0005);  // under the DMT limit 0.3 (R = 3 um: 0.338, outside)
}
