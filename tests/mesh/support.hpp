// SPDX-License-Identifier: MIT
// What the mesh file tests share (tests/mesh): a fresh scratch folder per test (created in SetUp,
// removed in TearDown) and a two-block mesh with every set of both boxes.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <system_error>

#include <unistd.h>

#include "mesh/box.hpp"
#include "mesh/mesh.hpp"

namespace tribex::mesh {

class ScratchDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("tribex_test_" + std::string(info->test_suite_name()) + "_" + std::to_string(::getpid()) + "_" + info->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::filesystem::path scratch_dir() const { return dir_; }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

 private:
  std::filesystem::path dir_;
};

/// A graded 4 x 3 x 5 box `substrate` (1 x 1 x 0.5 um) and a 2 x 2 x 2 box `tip` above it, with the
/// box generator's sets (NAME_xmin .. NAME_zmax, NAME_all); callers add the sets they test.
inline Mesh two_boxes() {
  BoxSpec a;
  a.name = "substrate";
  a.size = {1.0e-6, 1.0e-6, 0.5e-6};
  a.intervals = {4, 3, 5};
  a.grade_toward = "zmax";
  a.grading_ratio = 1.25;
  BoxSpec b;
  b.name = "tip";
  b.origin = {0.25e-6, 0.25e-6, 0.6e-6};
  b.size = {0.3e-6, 0.3e-6, 0.2e-6};
  b.intervals = {2, 2, 2};
  Mesh m = generate_box(a);
  append(m, generate_box(b));
  return m;
}

}  // namespace tribex::mesh
