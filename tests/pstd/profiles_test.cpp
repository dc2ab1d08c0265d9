// SPDX-License-Identifier: MIT
// Profile sources of the PSTD model: the seeded synthetic line (determinism, RMS, autocorrelation), linear
// oversampling, the text profile reader and lines cut out of the real AFM samples (read by mesh/afm).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "mesh/afm/height_map.hpp"
#include "tools/common/errors.hpp"
#include "tools/pstd/profile_sources.hpp"
#include "tools/pstd/profiles.hpp"

using namespace tribex::pstd;

TEST(PstdProfiles, SyntheticLineIsDeterministicWithExactRms) {
  const auto a = synthetic_line(4096, 10e-9, 2.7e-9, 40e-9, 7, 0);
  const auto b = synthetic_line(4096, 10e-9, 2.7e-9, 40e-9, 7, 0);
  const auto c = synthetic_line(4096, 10e-9, 2.7e-9, 40e-9, 8, 0);
  const auto d = synthetic_line(4096, 10e-9, 2.7e-9, 40e-9, 7, 1);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_NE(a, d);
  double mean = 0, sq = 0;
  for (double z : a) { mean += z; sq += z * z; }
  EXPECT_NEAR(mean / 4096, 0.0, 1e-22);
  EXPECT_NEAR(std::sqrt(sq / 4096), 2.7e-9, 1e-21);
}

TEST(PstdProfiles, SyntheticLineHasGaussianAutocorrelation) {
  // ACF exp(-x^2/xi^2): at lag xi it is e^-1, at 2 xi e^-4. xi = 10 samples over 2^16 samples: the standard
  // error of the sample ACF is about sqrt(2 xi / n) ~ 0.02, so 0.06 is a 3-sigma tolerance.
  const std::size_t n = 1 << 16;
  const auto z = synthetic_line(n, 1.0, 1.0, 10.0, 3, 0);
  auto acf = [&](std::size_t lag) {
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += z[i] * z[(i + lag) % n];
    return s / static_cast<double>(n);
  };
  EXPECT_NEAR(acf(10), std::exp(-1.0), 0.06);
  EXPECT_NEAR(acf(20), std::exp(-4.0), 0.06);
  EXPECT_NEAR(acf(5), std::exp(-0.25), 0.06);
}

TEST(PstdProfiles, OversamplingIsLinearAndPeriodicWrapCloses) {
  const std::vector<double> x{0, 10, 20, 30}, z{0, 10, 30, 60};
  const auto fine = resample(x, z, 0.0, 1.0, 40, true);
  EXPECT_DOUBLE_EQ(fine[5], 5.0);
  EXPECT_DOUBLE_EQ(fine[25], 45.0);
  EXPECT_DOUBLE_EQ(fine[35], 30.0);  // halfway from 60 (x = 30) back to 0 (x = 40 == 0)
  std::vector<double> tilted{1, 2, 3, 4, 5};
  level(tilted);
  for (double v : tilted) EXPECT_NEAR(v, 0.0, 1e-15);
}

TEST(PstdProfiles, ReadsProfileFilesWithUnitsAndRejectsBadOnesWithFileAndLine) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_pstd_profiles_test";
  std::filesystem::create_directories(dir);
  const std::string good = (dir / "good.csv").string(), bad = (dir / "bad.csv").string(),
                    one = (dir / "one.txt").string();
  std::ofstream(good) << "# a profile\nx[nm],z[nm]\n0,1\n10,2\n20,-1\n";
  std::ofstream(bad) << "x[nm],z[nm]\n0,1\n10,2\n5,oops\n";
  std::ofstream(one) << "1e-9\n2e-9\n3e-9\n";
  const RawProfile p = read_profile_file(good, std::nullopt);
  ASSERT_EQ(p.z.size(), 3u);
  EXPECT_DOUBLE_EQ(p.x[1], 10e-9);
  EXPECT_DOUBLE_EQ(p.z[2], -1e-9);
  try {
    read_profile_file(bad, std::nullopt);
    FAIL() << "expected BadInput";
  } catch (const tribex::tools::BadInput& e) {
    EXPECT_NE(std::string(e.what()).find(bad + ":4:"), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_profile_file(one, std::nullopt), tribex::tools::BadInput);  // needs --dx
  EXPECT_DOUBLE_EQ(read_profile_file(one, 5e-9).x[2], 10e-9);
  std::filesystem::remove_all(dir);
}

TEST(PstdProfiles, CutsLinesOutOfTheGwyddionMatrixSample) {
  // Read by mesh/afm; row 0 is the first line of the file, pixel = 10 um / 256.
  const auto map = tribex::mesh::afm::read_height_map(std::string(TRIBEX_AFM_DATA_DIR) + "/matrix-3.txt");
  const RawProfile row = map_row(map, 0);
  ASSERT_EQ(row.z.size(), 256u);
  EXPECT_NEAR(row.z[0], 1.8823e-8, 1e-13);  // first value of the file
  EXPECT_NEAR(row.z[1], 1.8497e-8, 1e-13);
  EXPECT_NEAR(row.mean_spacing(), 10e-6 / 256, 1e-15);
  const Profile seg = window_fine(map_column(map, 3), 1e-6, 2e-6, 1e-9, true);
  EXPECT_EQ(seg.z.size(), 2000u);
  EXPECT_NEAR(seg.source_dx, 10e-6 / 256, 1e-15);
}

TEST(PstdProfiles, CutsLinesOutOfGsfAndNanoscopeMaps) {
  // example_gsf.gsf: XRes 256, YRes 128, XReal 20 um, YReal 10 um -> rows along x at 78.125 nm, columns along y
  // at 78.125 nm; the profile holds the reader's heights unchanged.
  const auto gsf = tribex::mesh::afm::read_height_map(std::string(TRIBEX_AFM_DATA_DIR) + "/example_gsf.gsf");
  const RawProfile row = map_row(gsf, 5), column = map_column(gsf, 7);
  ASSERT_EQ(row.z.size(), 256u);
  ASSERT_EQ(column.z.size(), 128u);
  EXPECT_NEAR(row.x[255], 255 * 20e-6 / 256, 1e-15);
  EXPECT_NEAR(column.x[127], 127 * 10e-6 / 128, 1e-15);
  EXPECT_EQ(row.z[9], gsf.at(9, 5));
  EXPECT_EQ(column.z[9], gsf.at(7, 9));
  EXPECT_NE(row.origin.find("example_gsf.gsf"), std::string::npos) << row.origin;
  // di-1.di: Nanoscope, 512 x 512 px over 500 nm (pixel 0.9766 nm, mesh/afm/README.md), first height channel.
  const auto di = tribex::mesh::afm::read_height_map(std::string(TRIBEX_AFM_DATA_DIR) + "/di-1.di");
  const RawProfile di_row = map_row(di, 100);
  ASSERT_EQ(di_row.z.size(), di.nx);
  EXPECT_NEAR(di_row.mean_spacing(), 500e-9 / 512, 1e-13);
  EXPECT_EQ(di_row.z[17], di.at(17, 100));
  EXPECT_NE(di_row.origin.find("di-1.di channel Height row 100"), std::string::npos) << di_row.origin;
}
