// SPDX-License-Identifier: MIT
// The closed-form Coulomb + viscous oscillator (tools/friction_test/oscillator.hpp) against the
// classical Coulomb decrement and an independent small-step RK4 integration.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tools/friction_test/oscillator.hpp"

namespace tribex::friction_test {
namespace {

constexpr double pi = std::numbers::pi;

// Undamped Coulomb oscillator released at rest from x0: each half cycle lasts pi/omega0 and the
// swing shrinks by 2 delta (energy balance: k/2 (A_n^2 - A_{n+1}^2) = F_d (A_n + A_{n+1})),
// so after one cycle x = x0 - 4 delta, exactly.
TEST(Oscillator, CoulombDecrementIsFourOffsetsPerCycle) {
  OscillatorParams p{13000.0, 0.0, 100e-9, 0.0, 0.0};
  const double x0 = 5e-6, period = 2 * pi / p.omega0;
  std::vector<double> t{0.0, period / 2, period, 2 * period}, x;
  ASSERT_TRUE(oscillator_positions(p, {0.0, x0, 0.0}, t, x));
  EXPECT_NEAR(x[1], -(x0 - 2 * p.coulomb_offset), 1e-15);
  EXPECT_NEAR(x[2], x0 - 4 * p.coulomb_offset, 1e-15);
  EXPECT_NEAR(x[3], x0 - 8 * p.coulomb_offset, 1e-15);
}

// The same oscillator stops at the first reversal with |x| <= delta: x_n = (-1)^n (x0 - 2 n delta).
TEST(Oscillator, UndampedCoulombStopsWhereTheSpringCannotOvercomeFriction) {
  OscillatorParams p{13000.0, 0.0, 300e-9, 0.0, 0.0};
  const double x0 = 5e-6;
  const StopPoint s = oscillator_stop(p, x0);
  int n = 0;
  double xn = x0;
  while (std::abs(xn) > p.coulomb_offset) {
    ++n;
    xn = (n % 2 == 1 ? -1.0 : 1.0) * (x0 - 2 * n * p.coulomb_offset);
  }
  EXPECT_EQ(s.reversals, n);
  EXPECT_NEAR(s.x, xn, 1e-15);
  EXPECT_NEAR(s.time, n * pi / p.omega0, 1e-15);
}

// RK4 of x'' = -omega0^2 (x - x_eq) - 2 sigma x' - omega0^2 delta sign(x'), with a step 1e-5 of a
// period and a stick test at sign changes; the first-order error at each reversal keeps the
// agreement at ~1e-4 of the amplitude, which bounds the closed form's error far below the fits'.
TEST(Oscillator, AgreesWithSmallStepRk4) {
  OscillatorParams p{13000.0, 130.0, 150e-9, 150e-9, 20e-9};
  const double x0 = 4e-6, v0 = 0.01;  // starts moving forward
  const double period = 2 * pi / p.omega0, h = period * 1e-5;
  auto accel = [&](double x, double v, double s) {
    return -p.omega0 * p.omega0 * (x - p.x_eq) - 2 * p.sigma * v - p.omega0 * p.omega0 * p.coulomb_offset * s;
  };
  double x = x0, v = v0, s = 1.0;
  std::vector<double> times, rk;
  const int steps = static_cast<int>(6 * period / h);
  for (int i = 0; i <= steps; ++i) {
    if (i % 5000 == 0) {
      times.push_back(i * h);
      rk.push_back(x);
    }
    if (s == 0.0) continue;
    const double k1x = v, k1v = accel(x, v, s);
    const double k2x = v + h / 2 * k1v, k2v = accel(x + h / 2 * k1x, v + h / 2 * k1v, s);
    const double k3x = v + h / 2 * k2v, k3v = accel(x + h / 2 * k2x, v + h / 2 * k2v, s);
    const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v, s);
    x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double v_new = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (v_new * s <= 0) {  // reversal: stick or turn
      v = 0.0;
      const double f = std::abs(x - p.x_eq);
      s = f <= p.stick_offset ? 0.0 : (x > p.x_eq ? -1.0 : 1.0);
    } else {
      v = v_new;
    }
  }
  std::vector<double> exact;
  ASSERT_TRUE(oscillator_positions(p, {0.0, x0, v0}, times, exact));
  double worst = 0;
  for (std::size_t i = 0; i < times.size(); ++i) worst = std::max(worst, std::abs(exact[i] - rk[i]));
  EXPECT_LT(worst, 1e-4 * x0);
  EXPECT_GT(times.size(), 100u);
}

TEST(Oscillator, RejectsOverdampedAndNegativeParameters) {
  std::vector<double> x;
  EXPECT_FALSE(oscillator_positions({100.0, 150.0, 0.0, 0.0, 0.0}, {}, {0.0}, x));
  EXPECT_FALSE(oscillator_positions({100.0, 1.0, -1e-9, 0.0, 0.0}, {}, {0.0}, x));
  EXPECT_FALSE(oscillator_positions({0.0, 0.0, 0.0, 0.0, 0.0}, {}, {0.0}, x));
}

}  // namespace
}  // namespace tribex::friction_test
