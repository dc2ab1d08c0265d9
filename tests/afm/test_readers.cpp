// SPDX-License-Identifier: MIT
// AFM readers against the real sample files of inputs/data/afm/ (values from their headers).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mesh/afm/height_map.hpp"
#include "mesh/afm/preprocess.hpp"
#include "mesh/mesh_error.hpp"

using namespace tribex::mesh::afm;

namespace {
const std::string afm_dir = std::string(TRIBEX_AFM_DATA_DIR) + "/";

double header_scaled(double count, double hard, double soft_nm, int bytes) {
  return count * hard / std::ldexp(1.0, 8 * bytes) * soft_nm * 1e-9;
}
}  // namespace

TEST(NanoscopeReader, PixelSizesAndChannelsMatchTheHeaders) {
  struct Case { const char* file; std::size_t n; double size; std::size_t channels; const char* first; };
  const Case cases[] = {{"di-1.di", 512, 500e-9, 4, "Height"},
                        {"di-2.di", 512, 300e-9, 3, "Height"},
                        {"di-3.di", 256, 10e-6, 4, "ZSensor"},
                        {"di-5.di", 512, 1e-6, 2, "ZSensor"}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    const auto chans = nanoscope_channels(afm_dir + c.file);
    ASSERT_EQ(chans.size(), c.channels);
    EXPECT_EQ(chans[0].name, c.first);
    EXPECT_TRUE(chans[0].is_height);
    const HeightMap m = read_height_map(afm_dir + c.file);
    EXPECT_EQ(m.nx, c.n);
    EXPECT_EQ(m.ny, c.n);
    EXPECT_NEAR(m.dx, c.size / static_cast<double>(c.n), 1e-12 * c.size);
    EXPECT_NEAR(m.dy, c.size / static_cast<double>(c.n), 1e-12 * c.size);
    EXPECT_EQ(m.channel, c.first);
    // A topography map of these scans has nm-scale relief, not metres or zero.
    const double r = rms(level_plane(m));
    EXPECT_GT(r, 1e-11);
    EXPECT_LT(r, 1e-6);
  }
}

TEST(NanoscopeReader, EveryHeightChannelLoadsAndOthersAreRefused) {
  // di-1: Height, Height, Phase, AmplitudeError; di-3: ZSensor, AmplitudeError, Phase, Height.
  EXPECT_NO_THROW(read_nanoscope(afm_dir + "di-1.di", 1));
  EXPECT_THROW(read_nanoscope(afm_dir + "di-1.di", 2), tribex::mesh::MeshError);
  EXPECT_THROW(read_nanoscope(afm_dir + "di-1.di", 3), tribex::mesh::MeshError);
  EXPECT_THROW(read_nanoscope(afm_dir + "di-1.di", 4), tribex::mesh::MeshError);
  const HeightMap h3 = read_nanoscope(afm_dir + "di-3.di", 3);
  EXPECT_EQ(h3.channel, "Height");
  EXPECT_NO_THROW(read_nanoscope(afm_dir + "di-2.di", 1));
  EXPECT_THROW(read_nanoscope(afm_dir + "di-2.di", 2), tribex::mesh::MeshError);  // Deflection
  // di-1 channel 1 is the same surface before flattening: after plane levelling both describe
  // the same grains, so their RMS agree within a factor 2 while the raw channel 1 is tilted.
  const double r0 = rms(level_plane(read_nanoscope(afm_dir + "di-1.di", 0)));
  const double r1 = rms(level_plane(read_nanoscope(afm_dir + "di-1.di", 1)));
  EXPECT_GT(r1 / r0, 0.5);
  EXPECT_LT(r1 / r0, 2.0);
}

TEST(NanoscopeReader, CountScalingFollowsTheHeaderFormula) {
  // di-3 ZSensor: Z scale 24.57563 V, Sens. ZsensSens 790.3658 nm/V, 16 bit; first stored count
  // is at byte 40960 and lands on the last row (y counted backwards).
  const std::string bytes = read_file_bytes(afm_dir + "di-3.di");
  const auto* d = reinterpret_cast<const unsigned char*>(bytes.data()) + 40960;
  const double count = static_cast<std::int16_t>(static_cast<std::uint16_t>(d[0] | (d[1] << 8)));
  const HeightMap m = read_nanoscope(afm_dir + "di-3.di", 0);
  EXPECT_DOUBLE_EQ(m.at(0, m.ny - 1), header_scaled(count, 24.57563, 790.3658, 2));
  // di-5 is 32-bit: count * VALUE / 2^32 * soft (README step 5).
  const std::string b5 = read_file_bytes(afm_dir + "di-5.di");
  const auto* d5 = reinterpret_cast<const unsigned char*>(b5.data()) + 80960;
  const double c5 = static_cast<std::int32_t>(static_cast<std::uint32_t>(d5[0]) | (static_cast<std::uint32_t>(d5[1]) << 8) |
                                              (static_cast<std::uint32_t>(d5[2]) << 16) | (static_cast<std::uint32_t>(d5[3]) << 24));
  const HeightMap m5 = read_nanoscope(afm_dir + "di-5.di", 0);
  EXPECT_DOUBLE_EQ(m5.at(0, m5.ny - 1), header_scaled(c5, 24.57600, 842.6266, 4));
}

TEST(GsfReader, ExampleFileWithFourBytePadding) {
  const HeightMap m = read_height_map(afm_dir + "example_gsf.gsf");
  EXPECT_EQ(m.nx, 256u);
  EXPECT_EQ(m.ny, 128u);
  EXPECT_NEAR(m.dx, 78.125e-9, 1e-18);
  EXPECT_NEAR(m.dy, 78.125e-9, 1e-18);
  EXPECT_EQ(m.channel, "Test image");
  // README: raw heights with an un-levelled tilt of about 0.58-0.85 um.
  double lo = 1e9, hi = -1e9;
  for (double h : m.heights) { lo = std::min(lo, h); hi = std::max(hi, h); }
  EXPECT_GT(hi - lo, 0.1e-6);
  EXPECT_LT(hi - lo, 2e-6);
}

TEST(GwyddionMatrixReader, Di3ZSensorAgreesWithItsGwyddionExport) {
  const HeightMap txt = read_height_map(afm_dir + "matrix-3.txt");
  EXPECT_EQ(txt.channel, "ZSensor");
  ASSERT_EQ(txt.nx, 256u);
  ASSERT_EQ(txt.ny, 256u);
  EXPECT_NEAR(txt.dx, 10e-6 / 256, 1e-15);
  const HeightMap di = level_plane(read_height_map(afm_dir + "di-3.di", 0));
  const HeightMap tx = level_plane(txt);
  double worst = 0.0;
  for (std::size_t i = 0; i < di.heights.size(); ++i) worst = std::max(worst, std::fabs(di.heights[i] - tx.heights[i]));
  const double r = rms(tx);
  EXPECT_LT(worst, 1e-3 * r) << "max |difference| " << worst << " m, RMS " << r << " m";
}

TEST(XyzReader, RoundTripOfARegularGridInNanometres) {
  const std::string path = ::testing::TempDir() + "/grid.xyz";
  {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fprintf(f, "# units: nm\n");
    for (int iy = 2; iy >= 0; --iy)
      for (int ix = 0; ix < 4; ++ix) std::fprintf(f, "%d, %d, %g\n", 5 * ix, 2 * iy, 0.5 * ix - iy);
    std::fclose(f);
  }
  const HeightMap m = read_height_map(path);
  EXPECT_EQ(m.nx, 4u);
  EXPECT_EQ(m.ny, 3u);
  EXPECT_NEAR(m.dx, 5e-9, 1e-20);
  EXPECT_NEAR(m.dy, 2e-9, 1e-20);
  EXPECT_NEAR(m.at(3, 2), (1.5 - 2) * 1e-9, 1e-20);
}
