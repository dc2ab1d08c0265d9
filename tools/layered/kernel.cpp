// SPDX-License-Identifier: MIT
// docs/theory.md 11.4.1. In each layer the z-dependence of the transformed fields (u_r ~ J1, u_z ~ J0,
// sigma_rz ~ J1, sigma_zz ~ J0; identical to plane strain with sin/cos) is spanned by four modes in
// t = xi z: two decaying, (a - Q t) e^-t and (b - Q t) e^-t for (f, g) = (U_r, U_z), Q = (a - b)/kappa,
// and two growing ones written from the layer's bottom (zeta = t - tau <= 0), (a + Q zeta) e^zeta and
// (b - Q zeta) e^zeta, Q = (a + b)/kappa, kappa = 3 - 4 nu (Eq. 11.4.2). Stresses are scaled by
// mu_top xi, so every entry of the system is O(1) at any xi h.
#include "tools/layered/kernel.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>

namespace tribex::layered {
namespace {

using State = std::array<double, 4>;  // f = U_r, g = U_z, S_rz/(mu_top xi), S_zz/(mu_top xi)

struct Medium {
  double kappa, lambda_over_mu, mu_ratio;  // 3 - 4 nu, lambda/mu, mu/mu_top
};

Medium medium(const Elastic& m, double mu_top) {
  const double nu = m.poisson;
  return {3.0 - 4.0 * nu, 2.0 * nu / (1.0 - 2.0 * nu), m.shear() / mu_top};
}

/// Mode `k` (0, 1 decaying with (a, b) = (1, 0), (0, 1); 2, 3 growing) of a layer of thickness tau
/// (in units of 1/xi) at local depth t in [0, tau].
State mode_state(const Medium& m, int k, double t, double tau) {
  const bool decaying = k < 2;
  const double a = (k % 2 == 0) ? 1.0 : 0.0, b = 1.0 - a;
  double f, g, df, dg;
  if (decaying) {
    const double q = (a - b) / m.kappa, e = std::exp(-t);
    f = (a - q * t) * e;
    g = (b - q * t) * e;
    df = (-q - (a - q * t)) * e;
    dg = (-q - (b - q * t)) * e;
  } else {
    const double q = (a + b) / m.kappa, z = t - tau, e = std::exp(z);
    f = (a + q * z) * e;
    g = (b - q * z) * e;
    df = (q + a + q * z) * e;
    dg = (-q + b - q * z) * e;
  }
  // sigma_rz = mu (dU_r/dz - xi U_z), sigma_zz = lambda (xi U_r + dU_z/dz) + 2 mu dU_z/dz, over mu_top xi.
  return {f, g, m.mu_ratio * (df - g), m.mu_ratio * (m.lambda_over_mu * (f + dg) + 2.0 * dg)};
}

}  // namespace

double surface_compliance(const Stack& stack, double xi) {
  const double mu_top = stack.top().shear();
  const std::size_t n_layers = stack.layers.size();
  const bool half_space = stack.substrate.has_value();
  if (n_layers == 0) return 1.0 / stack.substrate->plane_strain();
  const int unknowns = 4 * static_cast<int>(n_layers) + (half_space ? 2 : 0);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(unknowns, unknowns);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(unknowns);
  int row = 0;
  // Surface: no shear, sigma_zz = -p (z points into the body; p = mu_top xi in these units).
  const Medium top = medium(stack.layers[0].material, mu_top);
  const double tau0 = xi * stack.layers[0].thickness;
  for (int k = 0; k < 4; ++k) {
    const State s = mode_state(top, k, 0.0, tau0);
    m(row, k) = s[2];
    m(row + 1, k) = s[3];
  }
  rhs(row + 1) = -1.0;
  row += 2;
  // Bonded interfaces: the whole state continuous.
  for (std::size_t i = 0; i < n_layers; ++i) {
    const Medium upper = medium(stack.layers[i].material, mu_top);
    const double tau = xi * stack.layers[i].thickness;
    const int col = 4 * static_cast<int>(i);
    const bool last = i + 1 == n_layers;
    const int rows_here = (last && !half_space) ? 2 : 4;  // rigid base: U_r = U_z = 0
    for (int k = 0; k < 4; ++k) {
      const State s = mode_state(upper, k, tau, tau);
      for (int r = 0; r < rows_here; ++r) m(row + r, col + k) = s[r];
    }
    if (!last) {
      const Medium lower = medium(stack.layers[i + 1].material, mu_top);
      const double tau_lower = xi * stack.layers[i + 1].thickness;
      for (int k = 0; k < 4; ++k) {
        const State s = mode_state(lower, k, 0.0, tau_lower);
        for (int r = 0; r < 4; ++r) m(row + r, col + 4 + k) = -s[r];
      }
    } else if (half_space) {
      const Medium base = medium(*stack.substrate, mu_top);
      for (int k = 0; k < 2; ++k) {  // decaying modes only
        const State s = mode_state(base, k, 0.0, 0.0);
        for (int r = 0; r < 4; ++r) m(row + r, col + 4 + k) = -s[r];
      }
    }
    row += rows_here;
  }
  const Eigen::VectorXd c = m.fullPivLu().solve(rhs);
  double uz = 0.0;
  for (int k = 0; k < 4; ++k) uz += c(k) * mode_state(top, k, 0.0, tau0)[1];
  // u_z^ = 2 C p^/xi with p^ = mu_top xi and u_z^ = uz: C = uz/(2 mu_top).
  return uz / (2.0 * mu_top);
}

double rigid_base_layer_compliance(const Layer& layer, double xi) {
  const double t = xi * layer.thickness, kappa = 3.0 - 4.0 * layer.material.poisson;
  // Numerator and denominator times 2 e^{-2t}, so that nothing overflows at large t.
  const double e2 = std::exp(-2.0 * t), e4 = e2 * e2;
  const double num = 2.0 * kappa * (1.0 - e4) - 8.0 * t * e2;
  const double den = 2.0 * kappa * (1.0 + e4) + 2.0 * (1.0 + kappa * kappa + 4.0 * t * t) * e2;
  return num / den / layer.material.plane_strain();
}

}  // namespace tribex::layered
