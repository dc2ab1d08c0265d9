// SPDX-License-Identifier: MIT
// Test helper: periodic random-phase surfaces with a prescribed isotropic PSD, by inverse 2-D FFT
// (a small radix-2 FFT written here; no FFTW in our dependencies).
//
// z(r) = sum over half the lattice q = 2 pi k / L of a_q cos(q.r + phi_q), a_q = 2 sqrt(C(q)) dq,
// phases uniform. On the periodic grid the modes are orthogonal, so <z^2> = sum_all C(q) dq^2, the
// lattice sum of m0 = int C d^2q (and likewise m2, m4): amplitudes are deterministic, phases random.
#pragma once

#include <cmath>
#include <complex>
#include <functional>
#include <random>
#include <vector>

#include "mesh/afm/height_map.hpp"

namespace tribex::test {

inline void fft_inplace(std::vector<std::complex<double>>& a, bool inverse) {
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {  // bit reversal
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double ang = 2 * M_PI / static_cast<double>(len) * (inverse ? 1 : -1);
    const std::complex<double> wl(std::cos(ang), std::sin(ang));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> w(1);
      for (std::size_t k = 0; k < len / 2; ++k) {
        const auto u = a[i + k], v = a[i + k + len / 2] * w;
        a[i + k] = u + v;
        a[i + k + len / 2] = u - v;
        w *= wl;
      }
    }
  }
}

/// n x n map (n a power of 2) with pixel size d (m) and isotropic PSD C(q) (q in 1/m, C in m^4).
inline mesh::afm::HeightMap synthetic_surface(std::size_t n, double d, const std::function<double(double)>& psd,
                                             unsigned seed) {
  const double L = static_cast<double>(n) * d, dq = 2 * M_PI / L;
  std::vector<std::complex<double>> z(n * n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> phase(0.0, 2 * M_PI);
  auto wrap = [n](long k) { return static_cast<std::size_t>((k % static_cast<long>(n) + static_cast<long>(n)) % static_cast<long>(n)); };
  const long h = static_cast<long>(n / 2);
  for (long ky = -h + 1; ky < h; ++ky) {
    for (long kx = -h + 1; kx < h; ++kx) {
      // Half plane: ky > 0, or ky == 0 and kx > 0; the conjugate fills the other half.
      if (!(ky > 0 || (ky == 0 && kx > 0))) continue;
      const double q = dq * std::sqrt(static_cast<double>(kx * kx + ky * ky));
      const double amp = std::sqrt(psd(q)) * dq;  // a_q / 2
      const std::complex<double> c = std::polar(amp, phase(rng));
      z[wrap(ky) * n + wrap(kx)] = c;
      z[wrap(-ky) * n + wrap(-kx)] = std::conj(c);
    }
  }
  // 2-D inverse DFT without normalisation: z(r) = sum_k Z_k exp(i q.r).
  std::vector<std::complex<double>> line(n);
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t c = 0; c < n; ++c) line[c] = z[r * n + c];
    fft_inplace(line, true);
    for (std::size_t c = 0; c < n; ++c) z[r * n + c] = line[c];
  }
  for (std::size_t c = 0; c < n; ++c) {
    for (std::size_t r = 0; r < n; ++r) line[r] = z[r * n + c];
    fft_inplace(line, true);
    for (std::size_t r = 0; r < n; ++r) z[r * n + c] = line[r];
  }
  mesh::afm::HeightMap m;
  m.nx = m.ny = n;
  m.dx = m.dy = d;
  m.heights.resize(n * n);
  for (std::size_t i = 0; i < n * n; ++i) m.heights[i] = z[i].real();
  m.channel = "synthetic";
  m.source = "synthetic";
  return m;
}

}  // namespace tribex::test
