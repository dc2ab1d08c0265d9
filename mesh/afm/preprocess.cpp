// SPDX-License-Identifier: MIT
#include "mesh/afm/preprocess.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh::afm {

HeightMap remove_mean(const HeightMap& map) {
  HeightMap out = map;
  double mean = 0.0;
  for (double h : map.heights) mean += h;
  mean /= static_cast<double>(map.heights.size());
  for (double& h : out.heights) h -= mean;
  return out;
}

HeightMap level_plane(const HeightMap& map) {
  // Normal equations of z = a + b x + c y on the pixel grid; x, y centred so the system is diagonal:
  // a = <z>, b = <z x>/<x^2>, c = <z y>/<y^2>.
  const double cx = 0.5 * static_cast<double>(map.nx - 1), cy = 0.5 * static_cast<double>(map.ny - 1);
  double sz = 0, szx = 0, szy = 0, sxx = 0, syy = 0;
  for (std::size_t iy = 0; iy < map.ny; ++iy) {
    for (std::size_t ix = 0; ix < map.nx; ++ix) {
      const double x = static_cast<double>(ix) - cx, y = static_cast<double>(iy) - cy, z = map.at(ix, iy);
      sz += z; szx += z * x; szy += z * y; sxx += x * x; syy += y * y;
    }
  }
  const double n = static_cast<double>(map.nx * map.ny);
  const double a = sz / n, b = szx / sxx, c = szy / syy;
  HeightMap out = map;
  for (std::size_t iy = 0; iy < map.ny; ++iy)
    for (std::size_t ix = 0; ix < map.nx; ++ix)
      out.at(ix, iy) -= a + b * (static_cast<double>(ix) - cx) + c * (static_cast<double>(iy) - cy);
  return out;
}

namespace {
std::string nm(double metres) {
  char b[64];
  std::snprintf(b, sizeof b, "%.6g nm", metres * 1e9);
  return b;
}
}  // namespace

HeightMap crop(const HeightMap& map, double x0, double y0, double wx, double wy) {
  if (!(wx > 0.0 && wy > 0.0 && x0 >= 0.0 && y0 >= 0.0) || x0 + wx > map.size_x() * (1 + 1e-9) ||
      y0 + wy > map.size_y() * (1 + 1e-9))
    throw MeshError(map.source + ": window at (" + nm(x0) + ", " + nm(y0) + ") of " + nm(wx) + " x " + nm(wy) +
                    " must be non-empty and inside the " + nm(map.size_x()) + " x " + nm(map.size_y()) + " map");
  const auto ix0 = static_cast<std::size_t>(std::ceil(x0 / map.dx - 0.5 - 1e-9));
  const auto iy0 = static_cast<std::size_t>(std::ceil(y0 / map.dy - 0.5 - 1e-9));
  const auto ix1 = std::min(map.nx, static_cast<std::size_t>(std::ceil((x0 + wx) / map.dx - 0.5 - 1e-9)));
  const auto iy1 = std::min(map.ny, static_cast<std::size_t>(std::ceil((y0 + wy) / map.dy - 0.5 - 1e-9)));
  if (ix1 < ix0 + 2 || iy1 < iy0 + 2)
    throw MeshError(map.source + ": window of " + nm(wx) + " x " + nm(wy) + " holds fewer than 2 x 2 pixels (pixel size " +
                    nm(map.dx) + "); enlarge it");
  HeightMap out;
  out.nx = ix1 - ix0;
  out.ny = iy1 - iy0;
  out.dx = map.dx;
  out.dy = map.dy;
  out.channel = map.channel;
  out.source = map.source;
  out.heights.reserve(out.nx * out.ny);
  for (std::size_t iy = iy0; iy < iy1; ++iy)
    for (std::size_t ix = ix0; ix < ix1; ++ix) out.heights.push_back(map.at(ix, iy));
  return out;
}

HeightMap resample(const HeightMap& map, std::size_t nx, std::size_t ny) {
  if (nx < 2 || ny < 2 || nx > 16384 || ny > 16384)
    throw MeshError(map.source + ": resampling to " + std::to_string(nx) + " x " + std::to_string(ny) +
                    " pixels is out of range (2 to 16384 per side)");
  HeightMap out;
  out.nx = nx;
  out.ny = ny;
  out.dx = map.size_x() / static_cast<double>(nx);
  out.dy = map.size_y() / static_cast<double>(ny);
  out.channel = map.channel;
  out.source = map.source;
  out.heights.resize(nx * ny);
  // Pixel centres map to pixel centres: u = (i + 1/2) * n_old / n_new - 1/2, clamped at the edges.
  for (std::size_t iy = 0; iy < ny; ++iy) {
    double v = (static_cast<double>(iy) + 0.5) * static_cast<double>(map.ny) / static_cast<double>(ny) - 0.5;
    v = std::clamp(v, 0.0, static_cast<double>(map.ny - 1));
    const auto j = std::min(static_cast<std::size_t>(v), map.ny - 2);
    const double fy = v - static_cast<double>(j);
    for (std::size_t ix = 0; ix < nx; ++ix) {
      double u = (static_cast<double>(ix) + 0.5) * static_cast<double>(map.nx) / static_cast<double>(nx) - 0.5;
      u = std::clamp(u, 0.0, static_cast<double>(map.nx - 1));
      const auto i = std::min(static_cast<std::size_t>(u), map.nx - 2);
      const double fx = u - static_cast<double>(i);
      out.heights[iy * nx + ix] = (1 - fx) * (1 - fy) * map.at(i, j) + fx * (1 - fy) * map.at(i + 1, j) +
                                  (1 - fx) * fy * map.at(i, j + 1) + fx * fy * map.at(i + 1, j + 1);
    }
  }
  return out;
}

HeightMap median_filter(const HeightMap& map) {
  HeightMap out = map;
  std::array<double, 9> w{};
  for (std::size_t iy = 0; iy < map.ny; ++iy) {
    for (std::size_t ix = 0; ix < map.nx; ++ix) {
      std::size_t k = 0;
      for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) {
          const long x = static_cast<long>(ix) + ox, y = static_cast<long>(iy) + oy;
          if (x >= 0 && y >= 0 && x < static_cast<long>(map.nx) && y < static_cast<long>(map.ny))
            w[k++] = map.at(static_cast<std::size_t>(x), static_cast<std::size_t>(y));
        }
      std::nth_element(w.begin(), w.begin() + static_cast<long>(k / 2), w.begin() + static_cast<long>(k));
      out.at(ix, iy) = w[k / 2];
    }
  }
  return out;
}

HeightMap smooth(const HeightMap& map) {
  HeightMap out = map;
  for (std::size_t iy = 0; iy < map.ny; ++iy) {
    for (std::size_t ix = 0; ix < map.nx; ++ix) {
      double s = 0.0, wsum = 0.0;
      for (int oy = -1; oy <= 1; ++oy)
        for (int ox = -1; ox <= 1; ++ox) {
          const long x = static_cast<long>(ix) + ox, y = static_cast<long>(iy) + oy;
          if (x < 0 || y < 0 || x >= static_cast<long>(map.nx) || y >= static_cast<long>(map.ny)) continue;
          const double wgt = (ox == 0 ? 2.0 : 1.0) * (oy == 0 ? 2.0 : 1.0);
          s += wgt * map.at(static_cast<std::size_t>(x), static_cast<std::size_t>(y));
          wsum += wgt;
        }
      out.at(ix, iy) = s / wsum;
    }
  }
  return out;
}

double rms(const HeightMap& map) {
  double mean = 0.0, sq = 0.0;
  for (double h : map.heights) mean += h;
  mean /= static_cast<double>(map.heights.size());
  for (double h : map.heights) sq += (h - mean) * (h - mean);
  return std::sqrt(sq / static_cast<double>(map.heights.size()));
}

}  // namespace tribex::mesh::afm
