// SPDX-License-Identifier: MIT
#include "solver/guards/strain_guard.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "solver/parallel/communicator.hpp"

namespace tribex::solver {

double largest_principal_strain(const double s[6], double lambda, double mu) {
  // eps = (sigma - c tr(sigma) I) / (2 mu), c = lambda / (3 lambda + 2 mu): Hooke's law inverted.
  const double c = lambda / (3.0 * lambda + 2.0 * mu);
  const double tr = s[0] + s[1] + s[2];
  const double a = 1.0 / (2.0 * mu);
  const double e[6] = {a * (s[0] - c * tr), a * (s[1] - c * tr), a * (s[2] - c * tr), a * s[3], a * s[4], a * s[5]};
  // Eigenvalues of the symmetric 3x3 (trigonometric form): m the mean, the deviator's invariants p and q.
  const double m = (e[0] + e[1] + e[2]) / 3.0;
  const double off = e[3] * e[3] + e[4] * e[4] + e[5] * e[5];
  const double d0 = e[0] - m, d1 = e[1] - m, d2 = e[2] - m;
  const double p2 = (d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * off) / 6.0;
  if (!(p2 > 0.0)) return std::abs(m);
  const double p = std::sqrt(p2);
  // det of the deviator / p, halved: r in [-1, 1]
  const double det = d0 * (d1 * d2 - e[4] * e[4]) - e[3] * (e[3] * d2 - e[4] * e[5]) + e[5] * (e[3] * e[4] - d1 * e[5]);
  const double r = std::clamp(det / (2.0 * p2 * p), -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  const double largest = m + 2.0 * p * std::cos(phi);
  const double smallest = m + 2.0 * p * std::cos(phi + 2.0 * M_PI / 3.0);
  return std::max(std::abs(largest), std::abs(smallest));
}

StrainGuard::StrainGuard(std::span<const ElementBlock> blocks, std::vector<int> global_element, long stride)
    : global_element_(std::move(global_element)), stride_(std::max(1L, stride)) {
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (const auto* elastic = std::get_if<materials::LinearElastic>(&blocks[b].material))
      watched_.push_back({static_cast<int>(b), elastic->lambda, elastic->mu});
}

StrainPeak StrainGuard::peak(std::span<const ElementBlock> blocks) const {
  StrainPeak peak;
  for (const auto& w : watched_) {
    const ElementBlock& b = blocks[static_cast<std::size_t>(w.block)];
    if (b.stress.size() < 6 * static_cast<std::size_t>(b.count)) continue;
    for (int e = 0; e < b.count; ++e) {
      const double strain = largest_principal_strain(&b.stress[6 * static_cast<std::size_t>(e)], w.lambda, w.mu);
      if (strain > peak.value) {
        const int local = b.first_element + e;
        peak = {strain, global_element_.empty() ? local : global_element_[static_cast<std::size_t>(local)], w.block};
      }
    }
  }
  if (parallel::size() > 1) {
    // The largest over the ranks with its element, then that element's block (every rank holds the same
    // block list).
    int element = peak.element;
    const double value = -parallel::min_location(-peak.value, element);
    const double block = parallel::max(element >= 0 && element == peak.element ? double(peak.block) : -1.0);
    peak = {value, element, static_cast<int>(block)};
  }
  return peak;
}

}  // namespace tribex::solver
