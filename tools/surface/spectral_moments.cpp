// SPDX-License-Identifier: MIT
#include "tools/surface/spectral_moments.hpp"

#include <cmath>

namespace tribex::surface {

Moments profile_moments(const mesh::afm::HeightMap& map, Direction along) {
  Moments m;
  double mean = 0.0;
  for (double h : map.heights) mean += h;
  mean /= static_cast<double>(map.heights.size());
  for (double h : map.heights) m.m0 += (h - mean) * (h - mean);
  m.m0 /= static_cast<double>(map.heights.size());
  const bool x = along == Direction::x;
  const std::size_t n_along = x ? map.nx : map.ny, n_across = x ? map.ny : map.nx;
  const double d = x ? map.dx : map.dy;
  double s2 = 0.0, s4 = 0.0;
  std::size_t count = 0;
  for (std::size_t j = 0; j < n_across; ++j) {
    for (std::size_t i = 1; i + 1 < n_along; ++i) {
      const double zm = x ? map.at(i - 1, j) : map.at(j, i - 1);
      const double z0 = x ? map.at(i, j) : map.at(j, i);
      const double zp = x ? map.at(i + 1, j) : map.at(j, i + 1);
      const double d1 = (zp - zm) / (2.0 * d);
      const double d2 = (zp - 2.0 * z0 + zm) / (d * d);
      s2 += d1 * d1;
      s4 += d2 * d2;
      ++count;
    }
  }
  m.m2 = s2 / static_cast<double>(count);
  m.m4 = s4 / static_cast<double>(count);
  return m;
}

Moments isotropic_moments(const mesh::afm::HeightMap& map) {
  const Moments a = profile_moments(map, Direction::x), b = profile_moments(map, Direction::y);
  return {a.m0, 0.5 * (a.m2 + b.m2), 0.5 * (a.m4 + b.m4)};
}

Moments combine(const Moments& a, const Moments& b) { return {a.m0 + b.m0, a.m2 + b.m2, a.m4 + b.m4}; }

SummitStatistics summit_statistics(const Moments& m) {
  SummitStatistics s;
  s.alpha = m.m0 * m.m4 / (m.m2 * m.m2);
  s.density = m.m4 / (6.0 * M_PI * std::sqrt(3.0) * m.m2);
  s.radius = 1.0 / ((8.0 / 3.0) * std::sqrt(m.m4 / M_PI));
  s.sigma_s = std::sqrt(std::max(0.0, 1.0 - 0.8968 / s.alpha) * m.m0);
  s.mean_height = 4.0 * std::sqrt(m.m0 / (M_PI * s.alpha));
  return s;
}

std::vector<Summit> find_summits(const mesh::afm::HeightMap& map) {
  std::vector<Summit> out;
  double mean = 0.0;
  for (double h : map.heights) mean += h;
  mean /= static_cast<double>(map.heights.size());
  for (std::size_t iy = 1; iy + 1 < map.ny; ++iy) {
    for (std::size_t ix = 1; ix + 1 < map.nx; ++ix) {
      const double z = map.at(ix, iy);
      bool top = true;
      for (int oy = -1; oy <= 1 && top; ++oy)
        for (int ox = -1; ox <= 1 && top; ++ox)
          if ((ox || oy) && map.at(ix + static_cast<std::size_t>(ox), iy + static_cast<std::size_t>(oy)) >= z) top = false;
      if (!top) continue;
      const double zxx = (map.at(ix + 1, iy) - 2 * z + map.at(ix - 1, iy)) / (map.dx * map.dx);
      const double zyy = (map.at(ix, iy + 1) - 2 * z + map.at(ix, iy - 1)) / (map.dy * map.dy);
      out.push_back({ix, iy, z - mean, -0.5 * (zxx + zyy)});
    }
  }
  return out;
}

}  // namespace tribex::surface
