// SPDX-License-Identifier: MIT
// Pre-processing: exactness on maps whose answer is known in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/afm/preprocess.hpp"
#include "mesh/mesh_error.hpp"

using namespace tribex::mesh::afm;

namespace {
HeightMap make_map(std::size_t nx, std::size_t ny, double d, double (*f)(double, double)) {
  HeightMap m;
  m.nx = nx; m.ny = ny; m.dx = d; m.dy = d;
  m.heights.resize(nx * ny);
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix) m.at(ix, iy) = f(static_cast<double>(ix) * d, static_cast<double>(iy) * d);
  return m;
}
}  // namespace

TEST(Preprocess, LevellingRemovesAnExactPlane) {
  const HeightMap m = make_map(40, 30, 1e-9, [](double x, double y) { return 3e-9 + 0.2 * x - 0.05 * y; });
  const HeightMap l = level_plane(m);
  for (double h : l.heights) EXPECT_NEAR(h, 0.0, 1e-20);
}

TEST(Preprocess, LevellingKeepsAZeroMeanCosine) {
  // cos with whole periods along x has no plane component: levelling leaves it almost intact (rms 1/sqrt2).
  const HeightMap m = make_map(64, 64, 1.0, [](double x, double) { return std::cos(2 * M_PI * 4 * x / 64); });
  EXPECT_NEAR(rms(level_plane(m)), std::sqrt(0.5), 0.01);
}

TEST(Preprocess, CropTakesTheWindowInPhysicalUnits) {
  // 100 nm x 100 nm region of a 500 nm map with 1 nm pixels, then a 35 nm x 100 nm track.
  const HeightMap m = make_map(500, 500, 1e-9, [](double x, double y) { return x + 1000 * y; });
  const HeightMap w = crop(m, 200e-9, 100e-9, 100e-9, 100e-9);
  EXPECT_EQ(w.nx, 100u);
  EXPECT_EQ(w.ny, 100u);
  EXPECT_NEAR(w.at(0, 0), 200e-9 + 1000 * 100e-9, 1e-15);
  const HeightMap t = crop(w, 0, 0, 35e-9, 100e-9);
  EXPECT_EQ(t.nx, 35u);
  EXPECT_EQ(t.ny, 100u);
  EXPECT_THROW(crop(m, 450e-9, 0, 100e-9, 10e-9), tribex::mesh::MeshError);
  EXPECT_THROW(crop(m, 0, 0, 0.5e-9, 10e-9), tribex::mesh::MeshError);
}

TEST(Preprocess, ResamplingReproducesALinearFieldAndKeepsTheArea) {
  const HeightMap m = make_map(16, 8, 2e-9, [](double x, double y) { return 0.3 * x + 0.1 * y; });
  const HeightMap r = resample(m, 64, 32);
  EXPECT_DOUBLE_EQ(r.size_x(), m.size_x());
  EXPECT_DOUBLE_EQ(r.size_y(), m.size_y());
  // Interior pixel centres: bilinear interpolation of a linear field is exact.
  for (std::size_t iy = 4; iy < 28; ++iy)
    for (std::size_t ix = 4; ix < 60; ++ix) {
      const double x = (static_cast<double>(ix) + 0.5) * r.dx - 0.5 * m.dx, y = (static_cast<double>(iy) + 0.5) * r.dy - 0.5 * m.dy;
      EXPECT_NEAR(r.at(ix, iy), 0.3 * x + 0.1 * y, 1e-18);
    }
}

TEST(Preprocess, MedianRemovesASpikeAndSmoothingKeepsAPlane) {
  HeightMap m = make_map(10, 10, 1.0, [](double, double) { return 1.0; });
  m.at(5, 5) = 100.0;
  EXPECT_DOUBLE_EQ(median_filter(m).at(5, 5), 1.0);
  const HeightMap p = make_map(10, 10, 1.0, [](double x, double y) { return 2 * x - y; });
  const HeightMap s = smooth(p);
  for (std::size_t iy = 1; iy < 9; ++iy)
    for (std::size_t ix = 1; ix < 9; ++ix) EXPECT_NEAR(s.at(ix, iy), p.at(ix, iy), 1e-12);
}
