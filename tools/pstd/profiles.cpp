// SPDX-License-Identifier: MIT
#include "tools/pstd/profiles.hpp"

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace tribex::pstd {

namespace {
// splitmix64: decorrelates (seed, stream) pairs before they seed the Mersenne twister.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}
double unit_open(std::mt19937_64& g) {  // uniform in (0, 1), from the top 53 bits
  return (static_cast<double>(g() >> 11) + 0.5) * 0x1.0p-53;
}
}  // namespace

void level(std::vector<double>& z) {
  const std::size_t n = z.size();
  if (n < 2) return;
  double sx = 0, sz = 0, sxx = 0, sxz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i);
    sx += x; sz += z[i]; sxx += x * x; sxz += x * z[i];
  }
  const double dn = static_cast<double>(n);
  const double slope = (dn * sxz - sx * sz) / (dn * sxx - sx * sx);
  const double intercept = (sz - slope * sx) / dn;
  for (std::size_t i = 0; i < n; ++i) z[i] -= intercept + slope * static_cast<double>(i);
}

std::vector<double> resample(const std::vector<double>& x_src, const std::vector<double>& z_src, double x0,
                             double dx, std::size_t n, bool periodic) {
  const std::size_t m = x_src.size();
  std::vector<double> xs = x_src, zs = z_src;
  if (periodic) {  // close the loop: the first sample again one mean spacing after the last
    const double mean_dx = (x_src.back() - x_src.front()) / static_cast<double>(m - 1);
    xs.push_back(x_src.back() + mean_dx);
    zs.push_back(z_src.front());
  }
  std::vector<double> out(n);
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = x0 + dx * static_cast<double>(i);
    while (k + 2 < xs.size() && xs[k + 1] <= x) ++k;
    if (x < xs.front() - 1e-9 * dx || x > xs.back() + 1e-9 * dx)
      throw std::logic_error("pstd::resample: position outside the source profile");
    const double w = (x - xs[k]) / (xs[k + 1] - xs[k]);
    out[i] = (1.0 - w) * zs[k] + w * zs[k + 1];
  }
  return out;
}

std::vector<double> synthetic_line(std::size_t n, double dx, double rms, double correlation_length,
                                   std::uint64_t seed, std::uint64_t stream) {
  std::mt19937_64 gen(mix(seed) ^ mix(stream + 0x51ed2701ULL));
  std::vector<double> white(n);
  for (std::size_t i = 0; i < n; i += 2) {  // Box-Muller, both outputs used
    const double r = std::sqrt(-2.0 * std::log(unit_open(gen)));
    const double phi = 2.0 * std::numbers::pi * unit_open(gen);
    white[i] = r * std::cos(phi);
    if (i + 1 < n) white[i + 1] = r * std::sin(phi);
  }
  // Kernel exp(-2x^2/xi^2) (variance xi^2/4): its self-convolution has variance xi^2/2, i.e. the
  // autocorrelation exp(-x^2/xi^2). Truncated at 2.5 xi, where it is exp(-12.5) ~ 4e-6.
  const long half = static_cast<long>(std::ceil(2.5 * correlation_length / dx));
  std::vector<double> kernel(2 * half + 1);
  for (long j = -half; j <= half; ++j) {
    const double x = static_cast<double>(j) * dx / correlation_length;
    kernel[j + half] = std::exp(-2.0 * x * x);
  }
  std::vector<double> z(n, 0.0);
  const long ln = static_cast<long>(n);
  for (long i = 0; i < ln; ++i) {
    double s = 0.0;
    for (long j = -half; j <= half; ++j) s += kernel[j + half] * white[((i + j) % ln + ln) % ln];
    z[i] = s;
  }
  // Zero mean only: a linear levelling would break the periodicity the substrate relies on.
  double mean = 0.0;
  for (double v : z) mean += v;
  mean /= static_cast<double>(n);
  for (double& v : z) v -= mean;
  double sq = 0.0;
  for (double v : z) sq += v * v;
  const double scale = sq > 0.0 ? rms / std::sqrt(sq / static_cast<double>(n)) : 0.0;
  for (double& v : z) v *= scale;
  return z;
}

std::size_t seeded_index(std::uint64_t seed, std::uint64_t stream, std::size_t n) {
  return n == 0 ? 0 : static_cast<std::size_t>(mix(mix(seed) ^ (stream * 0x2545f4914f6cdd1dULL)) % n);
}

}  // namespace tribex::pstd
