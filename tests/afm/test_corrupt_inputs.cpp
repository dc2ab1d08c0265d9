// SPDX-License-Identifier: MIT
// Corrupt variants of the real sample files (truncated, wrong sizes, NaN, zero pixels, absurd scales...):
// every reader must throw one MeshError naming the file, never crash or return a half-read map.
#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <cstring>
#include <limits>
#include <functional>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

#include "mesh/afm/height_map.hpp"
#include "mesh/mesh_error.hpp"

using namespace tribex::mesh::afm;
using tribex::mesh::MeshError;

namespace {
const std::string afm_dir = std::string(TRIBEX_AFM_DATA_DIR) + "/";

std::string write_variant(const std::string& name, const std::string& bytes) {
  const std::string path = ::testing::TempDir() + "/corrupt_" + name;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  return path;
}

/// Replaces the first occurrence of `from` at or after `after` (must exist in the original).
std::string replace_first(std::string s, const std::string& from, const std::string& to, std::size_t after = 0) {
  const auto p = s.find(from, after);
  EXPECT_NE(p, std::string::npos) << "test setup: '" << from << "' not found";
  if (p != std::string::npos) s.replace(p, from.size(), to);
  return s;
}

void expect_one_line_error(const std::string& name, const std::string& bytes,
                           const std::function<HeightMap(const std::string&)>& reader) {
  SCOPED_TRACE(name);
  const std::string path = write_variant(name, bytes);
  try {
    reader(path);
    ADD_FAILURE() << "no error for " << name;
  } catch (const MeshError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
  }
}
}  // namespace

TEST(CorruptInputs, Nanoscope) {
  const std::string base = read_file_bytes(afm_dir + "di-3.di");
  const std::size_t img = base.find("\\*Ciao image list");
  auto rd = [](const std::string& p) { return read_height_map(p, -1); };
  expect_one_line_error("empty.di", "\\*File list\r\n", rd);
  expect_one_line_error("header_cut.di", base.substr(0, 20000), rd);
  expect_one_line_error("data_cut.di", base.substr(0, 100000), rd);
  expect_one_line_error("bpp3.di", replace_first(base, "Bytes/pixel: 2", "Bytes/pixel: 3", img), rd);
  expect_one_line_error("samps_huge.di", replace_first(base, "Samps/line: 256", "Samps/line: 999", img), rd);
  expect_one_line_error("zero_lines.di", replace_first(base, "Number of lines: 256", "Number of lines: 0  ", img), rd);
  expect_one_line_error("lines_text.di", replace_first(base, "Number of lines: 256", "Number of lines: abc", img), rd);
  expect_one_line_error("scan_unit.di", replace_first(base, "Scan Size: 10 10 ~m", "Scan Size: 10 10 xx", img), rd);
  expect_one_line_error("scan_zero.di", replace_first(base, "Scan Size: 10 10 ~m", "Scan Size: 0 10 ~m ", img), rd);
  expect_one_line_error("zscale_absurd.di", replace_first(base, "24.57563 V", "9.9e+99  V", img), rd);
  expect_one_line_error("zscale_zero.di", replace_first(base, "24.57563 V", "0.000000 V", img), rd);
  expect_one_line_error("offset_far.di", replace_first(base, "Data offset: 40960", "Data offset: 99999999", img), rd);
  expect_one_line_error("no_end.di", replace_first(base, "\\*File list end", "\\*File list enX"), rd);
  expect_one_line_error("bad_line.di", replace_first(base, "\\Bytes/pixel", "XBytes/pixel", img), rd);
  expect_one_line_error("header_len.di", replace_first(base, "Data length: 40960", "Data length: 9999999"), rd);
  expect_one_line_error("no_channels.di", replace_first(base, "\\*Ciao image list", "\\*Ciao imagX list"), [](const std::string& p) {
    // with the first section renamed, channel 3 no longer exists
    return read_nanoscope(p, 3);
  });
  expect_one_line_error("channel9.di", base, [](const std::string& p) { return read_nanoscope(p, 9); });
}

TEST(CorruptInputs, Gsf) {
  const std::string base = read_file_bytes(afm_dir + "example_gsf.gsf");
  auto rd = [](const std::string& p) { return read_height_map(p); };
  auto with_float = [&](float v) {
    std::string s = base;
    std::memcpy(s.data() + 156 + 4 * 1000, &v, 4);
    return s;
  };
  expect_one_line_error("data_cut.gsf", base.substr(0, 100000), rd);
  expect_one_line_error("header_cut.gsf", base.substr(0, 60), rd);
  expect_one_line_error("extra_byte.gsf", base + "x", rd);
  expect_one_line_error("xres_big.gsf", replace_first(base, "XRes = 256", "XRes = 999"), rd);
  expect_one_line_error("xres_zero.gsf", replace_first(base, "XRes = 256", "XRes = 000"), rd);
  expect_one_line_error("yres_neg.gsf", replace_first(base, "YRes = 128", "YRes = -12"), rd);
  expect_one_line_error("no_xres.gsf", replace_first(base, "XRes = 256", "XRex = 256"), rd);
  expect_one_line_error("bad_magic.gsf", replace_first(base, "Gwyddion Simple Field 1.0", "Gwyddion Simple Field 1.0x"),
                        [](const std::string& p) { return read_gsf(p); });
  expect_one_line_error("nan.gsf", with_float(std::numeric_limits<float>::quiet_NaN()), rd);
  expect_one_line_error("inf.gsf", with_float(std::numeric_limits<float>::infinity()), rd);
  expect_one_line_error("absurd_z.gsf", with_float(1e10f), rd);
  expect_one_line_error("absurd_xreal.gsf", replace_first(base, "XReal = 2e-05", "XReal = 2e+05"), rd);
  expect_one_line_error("zunits.gsf", replace_first(base, "ZUnits = m", "ZUnits = V"), rd);
  expect_one_line_error("no_equals.gsf", replace_first(base, "Title = Test image", "Title : Test image"), rd);
}

TEST(CorruptInputs, GwyddionMatrix) {
  const std::string base = read_file_bytes(afm_dir + "matrix-3.txt");
  const std::size_t data = base.find("\n", base.find("Value units")) + 1;
  auto rd = [](const std::string& p) { return read_height_map(p); };
  const std::string first_value = base.substr(data, base.find('\t', data) - data);
  expect_one_line_error("cut.txt", base.substr(0, base.size() / 2), rd);
  expect_one_line_error("nan.txt", replace_first(base, first_value, "nan", data), rd);
  expect_one_line_error("text.txt", replace_first(base, first_value, "abc", data), rd);
  expect_one_line_error("suffix.txt", replace_first(base, first_value, first_value + "x", data), rd);
  expect_one_line_error("absurd.txt", replace_first(base, first_value, "1e5", data), rd);
  expect_one_line_error("extra_value.txt", replace_first(base, "\n", "\t1e-9\n", data), rd);
  expect_one_line_error("no_width.txt", replace_first(base, "# Width", "# Wodth"), rd);
  expect_one_line_error("neg_width.txt", replace_first(base, "# Width: 10.00", "# Width: -10.0"), rd);
  expect_one_line_error("width_unit.txt", replace_first(base, "# Height: 10.00 \xc2\xb5m", "# Height: 10.00 furlong"), rd);
  expect_one_line_error("value_units.txt", replace_first(base, "# Value units: m", "# Value units: V"), rd);
  expect_one_line_error("header_only.txt", base.substr(0, data), rd);
  expect_one_line_error("one_row.txt", base.substr(0, base.find('\n', data) + 1), rd);
}

TEST(CorruptInputs, XyzText) {
  auto rd = [](const std::string& p) { return read_xyz_text(p); };
  const std::string good = "0 0 1e-9\n1e-9 0 2e-9\n0 1e-9 3e-9\n1e-9 1e-9 4e-9\n";
  ASSERT_NO_THROW(read_xyz_text(write_variant("good.xyz", good)));
  expect_one_line_error("two_cols.xyz", good + "1 2\n", rd);
  expect_one_line_error("four_cols.xyz", "0 0 1 1\n" + good, rd);
  expect_one_line_error("nan.xyz", replace_first(good, "4e-9", "nan"), rd);
  expect_one_line_error("text.xyz", replace_first(good, "4e-9", "abc"), rd);
  expect_one_line_error("missing.xyz", good.substr(0, good.rfind("1e-9 1e-9")), rd);
  expect_one_line_error("duplicate.xyz", good + "1e-9 1e-9 5e-9\n", rd);
  expect_one_line_error("uneven.xyz", good + "3e-9 0 1e-9\n3e-9 1e-9 1e-9\n", rd);
  expect_one_line_error("unit.xyz", "# units: furlong\n" + good, rd);
  expect_one_line_error("empty.xyz", "", rd);
  expect_one_line_error("one_point.xyz", "0 0 0\n", rd);
  expect_one_line_error("absurd.xyz", replace_first(good, "4e-9", "4e3"), rd);
  expect_one_line_error("line.xyz", "0 0 0\n1e-9 0 0\n2e-9 0 0\n3e-9 0 0\n", rd);
}

// Issue 29, items 7-11: the readers open only regular files of a size a map can have, say which format
// the extension asked for, refuse scales that would invert or uncalibrate the surface, and name header
// lines as FILE:LINE:COL.
namespace {
std::string error_of(const std::string& path) {
  try {
    read_height_map(path);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST(CorruptInputs, OnlyRegularFilesOfAMapSize) {
  EXPECT_NE(error_of("/dev/zero").find("/dev/zero: not a regular file"), std::string::npos) << error_of("/dev/zero");
  const std::string fifo = ::testing::TempDir() + "/corrupt_fifo.di";
  std::remove(fifo.c_str());
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(error_of(fifo).find("not a regular file"), std::string::npos);  // returns: nothing opened the pipe
  std::remove(fifo.c_str());
  // A sparse file whose size claims a map far beyond any AFM scan: refused before it is read.
  const std::string big = write_variant("sparse.gsf", "Gwyddion Simple Field 1.0\nXRes = 65536\nYRes = 65536\n");
  ASSERT_EQ(truncate(big.c_str(), (off_t(1) << 31) + 100), 0);
  EXPECT_NE(error_of(big).find("more than the 1024 MiB"), std::string::npos) << error_of(big);
  std::remove(big.c_str());
  EXPECT_NE(error_of(write_variant("empty.di", "")).find("the file is empty"), std::string::npos);
  const std::string text = "0 0 1e-9\n1e-9 0 2e-9\n0 1e-9 3e-9\n1e-9 1e-9 4e-9\n";
  const std::string gsf = write_variant("text.gsf", text), di = write_variant("text.di", text);
  EXPECT_NE(error_of(gsf).find(gsf + ":1:1: a .gsf file must start with 'Gwyddion Simple Field 1.0'"), std::string::npos)
      << error_of(gsf);
  EXPECT_NE(error_of(di).find(di + ":1:1: a Nanoscope file"), std::string::npos) << error_of(di);
  EXPECT_NO_THROW(read_height_map(write_variant("text.xyz", text)));  // the same text as .xyz is a map
}

TEST(CorruptInputs, ScalesThatInvertOrUncalibrate) {
  const std::string base = read_file_bytes(afm_dir + "di-3.di");
  const std::size_t img = base.find("\\*Ciao image list");
  auto rd = [](const std::string& p) { return read_height_map(p, -1); };
  expect_one_line_error("zscale_negative.di", replace_first(base, "24.57563 V", "-24.5756 V", img), rd);
  expect_one_line_error("zsens_nan.di", replace_first(base, "Zsens: V 34.55678 nm/V", "Zsens: V nan nm/V"), rd);
  expect_one_line_error("zsens_negative.di", replace_first(base, "Zsens: V 34.55678 nm/V", "Zsens: V -34.5567 nm/V"), rd);
  // Header errors name the line: FILE:LINE:1 (line 144 holds the Zsens sensitivity).
  const std::string path = write_variant("zsens_line.di", replace_first(base, "Zsens: V 34.55678 nm/V", "Zsens: V -34.5567 nm/V"));
  EXPECT_NE(error_of(path).find(path + ":144:1: "), std::string::npos) << error_of(path);
  const std::string gsf = read_file_bytes(afm_dir + "example_gsf.gsf");
  expect_one_line_error("xreal_tiny.gsf", replace_first(gsf, "XReal = 2e-05", "XReal = 2e-300"), rd);
}
