// SPDX-License-Identifier: MIT
// tools/common: JSON string/number formatting (RFC 8259) and the write-through-rename text file.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "tools/common/errors.hpp"
#include "tools/common/json.hpp"
#include "tools/common/text_file.hpp"

using namespace tribex::tools;

TEST(ToolsJson, StringsAreQuotedAndEscaped) {
  EXPECT_EQ(json_string("di-1.di row 3"), "\"di-1.di row 3\"");
  EXPECT_EQ(json_string("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(json_string(std::string("t\tn\n\x01", 5)), "\"t\\u0009n\\u000a\\u0001\"");
  EXPECT_EQ(json_string("µm"), "\"µm\"");  // UTF-8 passes through
}

TEST(ToolsJson, NumbersKeepNineDigitsAndNonFiniteIsNull) {
  EXPECT_EQ(json_number(0.5), "0.5");
  EXPECT_EQ(json_number(1.0 / 3.0), "0.333333333");
  EXPECT_EQ(json_number(-2.5e-12), "-2.5e-12");
  EXPECT_EQ(json_number(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(json_number(-std::numeric_limits<double>::infinity()), "null");
}

TEST(ToolsTextFile, WritesWholeFileAndLeavesNoTemporary) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_tools_text_file_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "out.csv").string();
  write_text_file(path, "a,b\n1,2\n");
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str(), "a,b\n1,2\n");
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  // A folder that does not exist: BadInput naming the path, and nothing written.
  const std::string missing = (dir / "no" / "out.csv").string();
  try {
    write_text_file(missing, "x\n");
    FAIL() << "expected BadInput";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "no"));
  std::filesystem::remove_all(dir);
}

// Only a regular file is replaced (issue 54, item 6): a FIFO, a folder or a symbolic link at the
// path or at its temporary name is BadInput naming it, and stays as it was.
TEST(ToolsTextFile, ReplacesOnlyRegularFiles) {
  namespace fs = std::filesystem;
  const fs::path d = fs::temp_directory_path() / ("tribex_text_targets_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d / "folder.csv");
  ASSERT_EQ(::mkfifo((d / "pipe.csv").c_str(), 0644), 0);
  ASSERT_EQ(::mkfifo((d / "tmp_pipe.csv.tmp").c_str(), 0644), 0);
  fs::create_symlink("elsewhere.csv", d / "link.csv");
  for (const char* name : {"pipe.csv", "folder.csv", "link.csv", "tmp_pipe.csv"}) {
    try {
      write_text_file((d / name).string(), "a,b\n");
      ADD_FAILURE() << name << " was written";
    } catch (const BadInput& e) {
      EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(fs::is_fifo(d / "pipe.csv"));
  EXPECT_TRUE(fs::is_directory(d / "folder.csv"));
  EXPECT_TRUE(fs::is_symlink(d / "link.csv"));
  EXPECT_FALSE(fs::exists(d / "elsewhere.csv"));
  write_text_file((d / "plain.csv").string(), "a,b\n");  // a new file, then a regular one replaced
  write_text_file((d / "plain.csv").string(), "c,d\n");
  std::ifstream in(d / "plain.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "c,d");
  fs::remove_all(d);
}
