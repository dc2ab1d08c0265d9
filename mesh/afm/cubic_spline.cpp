// SPDX-License-Identifier: MIT
// Interpolating cubic spline (de Boor, "A Practical Guide to Splines", ch. IV): on [x_i, x_i + h] with
// t = (x - x_i)/h, S = (1-t) y_i + t y_{i+1} + h^2/6 [((1-t)^3 - (1-t)) M_i + (t^3 - t) M_{i+1}].
#include "mesh/afm/cubic_spline.hpp"

#include <algorithm>
#include <cmath>

namespace tribex::mesh::afm {
namespace {

double evaluate(const double* y, const double* m, std::size_t n, double x0, double h, double x) {
  if (n == 1) return y[0];
  const double u = (x - x0) / h;
  const auto i = static_cast<std::size_t>(std::clamp(std::floor(u), 0.0, static_cast<double>(n - 2)));
  const double t = u - static_cast<double>(i), s = 1.0 - t;
  return s * y[i] + t * y[i + 1] + h * h / 6.0 * ((s * s * s - s) * m[i] + (t * t * t - t) * m[i + 1]);
}

}  // namespace

std::vector<double> spline_moments(const double* y, std::size_t n, double h, SplineEnds ends) {
  std::vector<double> m(n, 0.0);
  if (n < 3) return m;
  // Interior unknowns M_1..M_{n-2}: rows M_{i-1} + 4 M_i + M_{i+1} = rhs_i. Not-a-knot substitutes
  // M_0 = 2 M_1 - M_2 into the first row (6 M_1 + 0 M_2 = rhs_1), likewise the last; with one
  // unknown (n = 3) both say M_0 = M_1 = M_2: the parabola. Diagonally dominant: no pivoting.
  const std::size_t k = n - 2;
  const bool nak = ends == SplineEnds::not_a_knot;
  std::vector<double> c(k), d(k);
  const double f = 6.0 / (h * h);
  for (std::size_t i = 0; i < k; ++i) {
    const double rhs = f * (y[i + 2] - 2.0 * y[i + 1] + y[i]);
    const bool first = i == 0, last = i + 1 == k;
    const double diag = nak && (first || last) ? 6.0 : 4.0;
    const double sub = nak && last ? 0.0 : 1.0, super = nak && first ? 0.0 : 1.0;
    const double denom = diag - (first ? 0.0 : sub * c[i - 1]);
    c[i] = super / denom;
    d[i] = (rhs - (first ? 0.0 : sub * d[i - 1])) / denom;
  }
  m[k] = d[k - 1];
  for (std::size_t i = k - 1; i-- > 0;) m[i + 1] = d[i] - c[i] * m[i + 2];
  if (nak) {
    m[0] = k == 1 ? m[1] : 2.0 * m[1] - m[2];
    m[n - 1] = k == 1 ? m[1] : 2.0 * m[n - 2] - m[n - 3];
  }
  return m;
}

CubicSpline::CubicSpline(double x0, double h, std::vector<double> values, SplineEnds ends)
    : x0_(x0), h_(h), y_(std::move(values)) {
  m_ = spline_moments(y_.data(), y_.size(), h_, ends);
}

double CubicSpline::operator()(double x) const { return evaluate(y_.data(), m_.data(), y_.size(), x0_, h_, x); }

SplineSurface::SplineSurface(const HeightMap& map) : map_(map), row_moments_(map.nx * map.ny) {
  for (std::size_t iy = 0; iy < map.ny; ++iy) {
    const auto m = spline_moments(&map.heights[iy * map.nx], map.nx, map.dx, SplineEnds::not_a_knot);
    std::copy(m.begin(), m.end(), row_moments_.begin() + static_cast<std::ptrdiff_t>(iy * map.nx));
  }
}

std::vector<double> SplineSurface::evaluate_grid(const std::vector<double>& xs, const std::vector<double>& ys) const {
  const std::size_t nx = map_.nx, ny = map_.ny, nq = xs.size();
  // Rows first: column q of `rows` holds the row splines evaluated at xs[q], one value per pixel row.
  std::vector<double> rows(nq * ny);
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t q = 0; q < nq; ++q)
      rows[q * ny + iy] = evaluate(&map_.heights[iy * nx], &row_moments_[iy * nx], nx, 0.5 * map_.dx, map_.dx, xs[q]);
  // Then columns: a spline along y through each column, evaluated at ys.
  std::vector<double> out(ys.size() * nq);
  for (std::size_t q = 0; q < nq; ++q) {
    const auto m = spline_moments(&rows[q * ny], ny, map_.dy, SplineEnds::not_a_knot);
    for (std::size_t j = 0; j < ys.size(); ++j)
      out[j * nq + q] = evaluate(&rows[q * ny], m.data(), ny, 0.5 * map_.dy, map_.dy, ys[j]);
  }
  return out;
}

double SplineSurface::operator()(double x, double y) const { return evaluate_grid({x}, {y})[0]; }

}  // namespace tribex::mesh::afm
