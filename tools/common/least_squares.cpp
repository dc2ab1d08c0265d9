// SPDX-License-Identifier: MIT
#include "tools/common/least_squares.hpp"

#include <cmath>
#include <stdexcept>

namespace tribex::tools {
namespace {

// Covariance from the SVD of J itself, J = U S V^T -> (J^T J)^-1 = V S^-2 V^T: forming J^T J
// squares the condition number and can turn a merely ill-conditioned fit into negative variances.
void fill_statistics(FitResult& r, const Eigen::MatrixXd& j_free, const std::vector<int>& free,
                     double sum_squares, std::size_t n, const Eigen::VectorXd& scale) {
  const std::size_t p = free.size();
  const double dof = n > p ? static_cast<double>(n - p) : 1.0;
  r.rms_residual = std::sqrt(sum_squares / static_cast<double>(n));
  r.residual_sigma = std::sqrt(sum_squares / dof);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(j_free, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  if (sv.size() == 0 || !(sv(sv.size() - 1) > 1e-13 * sv(0)))
    throw std::runtime_error("the fit is degenerate (J rank-deficient): the data do not determine all parameters");
  const Eigen::MatrixXd v = svd.matrixV();
  const Eigen::MatrixXd cov_q =
      v * sv.array().square().inverse().matrix().asDiagonal() * v.transpose() * (sum_squares / dof);
  const auto np = static_cast<int>(r.parameters.size());
  r.covariance = Eigen::MatrixXd::Zero(np, np);
  for (std::size_t a = 0; a < p; ++a)
    for (std::size_t b = 0; b < p; ++b)
      r.covariance(free[a], free[b]) = cov_q(a, b) * scale(free[a]) * scale(free[b]);
  r.correlation = Eigen::MatrixXd::Identity(np, np);
  for (int a = 0; a < np; ++a)
    for (int b = 0; b < np; ++b) {
      const double d = std::sqrt(r.covariance(a, a) * r.covariance(b, b));
      if (a != b && d > 0) r.correlation(a, b) = r.covariance(a, b) / d;
    }
}

}  // namespace

FitResult levenberg_marquardt(const ResidualFunction& residuals, Eigen::VectorXd start,
                              const Eigen::VectorXd& scale, const LmOptions& options) {
  const auto np = static_cast<int>(start.size());
  std::vector<int> free;
  for (int i = 0; i < np; ++i)
    if (options.fixed.empty() || !options.fixed[static_cast<std::size_t>(i)]) free.push_back(i);
  const auto nf = static_cast<int>(free.size());

  auto r0 = residuals(start);
  if (!r0) throw std::runtime_error("the start point of the fit is outside the model's domain");
  Eigen::VectorXd p = start, r = *r0;
  double s = r.squaredNorm();
  double lambda = 1e-3;
  FitResult out;
  Eigen::MatrixXd jtj;

  // Forward-difference Jacobian in the scaled variables q (step 1e-7 of the typical size).
  auto jacobian = [&](const Eigen::VectorXd& at, const Eigen::VectorXd& r_at) {
    Eigen::MatrixXd j(r_at.size(), nf);
    for (int a = 0; a < nf; ++a) {
      const int i = free[static_cast<std::size_t>(a)];
      Eigen::VectorXd shifted = at;
      double h = 1e-7 * scale(i);
      shifted(i) += h;
      auto rs = residuals(shifted);
      if (!rs) {  // at the domain edge: step the other way
        shifted(i) = at(i) - h;
        rs = residuals(shifted);
        h = -h;
        if (!rs) throw std::runtime_error("the model is undefined on both sides of a parameter");
      }
      j.col(a) = (*rs - r_at) / (h / scale(i));
    }
    return j;
  };

  Eigen::MatrixXd j = jacobian(p, r);
  for (out.iterations = 0; out.iterations < options.max_iterations; ++out.iterations) {
    jtj = j.transpose() * j;
    const Eigen::VectorXd g = j.transpose() * r;
    bool improved = false;
    double s_new = s;
    for (int attempt = 0; attempt < 30 && !improved; ++attempt) {
      Eigen::MatrixXd a = jtj;
      for (int k = 0; k < nf; ++k) a(k, k) += lambda * std::max(jtj(k, k), 1e-30);
      const Eigen::VectorXd dq = a.ldlt().solve(-g);
      Eigen::VectorXd trial = p;
      for (int k = 0; k < nf; ++k) trial(free[static_cast<std::size_t>(k)]) += dq(k) * scale(free[static_cast<std::size_t>(k)]);
      auto rt = residuals(trial);
      if (rt && rt->squaredNorm() < s) {
        s_new = rt->squaredNorm();
        p = trial;
        r = *rt;
        lambda = std::max(lambda / 10, 1e-12);
        improved = true;
      } else {
        lambda *= 10;
      }
    }
    if (!improved) {  // no downhill step at any damping: we are at the minimum to round-off
      out.converged = true;
      break;
    }
    const double drop = (s - s_new) / std::max(s, 1e-300);
    s = s_new;
    j = jacobian(p, r);
    if (drop < options.relative_tolerance) {
      out.converged = true;
      break;
    }
  }
  out.parameters = p;
  fill_statistics(out, j, free, s, static_cast<std::size_t>(r.size()), scale);
  return out;
}

FitResult fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size() || x.size() < 3) throw std::runtime_error("fit_line needs at least 3 points");
  const auto n = static_cast<Eigen::Index>(x.size());
  // Centre and scale x and y so the normal equations are well conditioned at any unit size.
  double xs = 0, ys = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    xs = std::max(xs, std::abs(x[static_cast<std::size_t>(i)]));
    ys = std::max(ys, std::abs(y[static_cast<std::size_t>(i)]));
  }
  if (xs == 0) xs = 1;
  if (ys == 0) ys = 1;
  Eigen::MatrixXd a(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = x[static_cast<std::size_t>(i)] / xs;
    b(i) = y[static_cast<std::size_t>(i)] / ys;
  }
  const Eigen::VectorXd q = a.colPivHouseholderQr().solve(b);
  FitResult out;
  out.parameters = Eigen::Vector2d(q(0) * ys, q(1) * ys / xs);
  const double s = (a * q - b).squaredNorm() * ys * ys;
  out.converged = true;
  const Eigen::Vector2d scale(ys, ys / xs);
  fill_statistics(out, a, {0, 1}, s / (ys * ys), static_cast<std::size_t>(n), scale);
  out.rms_residual *= ys;
  out.residual_sigma *= ys;
  return out;
}

}  // namespace tribex::tools
