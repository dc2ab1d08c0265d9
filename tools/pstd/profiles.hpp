// SPDX-License-Identifier: MIT
// 1-D height profiles for the PSTD model: the source side (a line of an AFM map, a profile file, a seeded
// synthetic rough line), levelling, and linear-interpolation oversampling onto the model grid (1 nm in the
// report). Heights and positions are SI (m).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tribex::pstd {

/// Heights z[i] at x = i * dx (uniform). `source_dx` is the spacing of the data this profile was made
/// from (the measured or generated spacing before oversampling); the model uses it as the span of the
/// curvature stencil, because below it the oversampled profile is piecewise linear.
struct Profile {
  double dx = 0.0;
  double source_dx = 0.0;
  std::vector<double> z;
  std::string origin;  // human description for summaries, e.g. "matrix-3.txt row 17"
  double length() const { return dx * static_cast<double>(z.size()); }
};

/// Subtract the least-squares straight line (AFM line levelling).
void level(std::vector<double>& z);

/// Linear interpolation of (x_src, z_src) (x strictly increasing) onto x = x0 + i*dx, i < n; x beyond the
/// data is an internal error (callers check). `periodic` joins the last sample to the first over one
/// source spacing (x_src.back() + mean spacing wraps to x_src.front()).
std::vector<double> resample(const std::vector<double>& x_src, const std::vector<double>& z_src, double x0,
                             double dx, std::size_t n, bool periodic);

/// Gaussian-correlated random line: white noise (own Box-Muller on std::mt19937_64, so identical on every
/// platform for a given seed) smoothed by the moving average k(x) = exp(-2 x^2/xi^2), |x| <= 2.5 xi,
/// with periodic wrap; this gives the autocorrelation exp(-x^2/xi^2). The result is levelled to zero
/// mean and scaled to the exact RMS `rms` over its n samples. `stream` selects an independent line for
/// the same seed (substrate = 0, counterface segments 1, 2, ...).
std::vector<double> synthetic_line(std::size_t n, double dx, double rms, double correlation_length,
                                   std::uint64_t seed, std::uint64_t stream);

/// Deterministic integer in [0, n) from (seed, stream): for "seeded random line" choices.
std::size_t seeded_index(std::uint64_t seed, std::uint64_t stream, std::size_t n);

}  // namespace tribex::pstd
