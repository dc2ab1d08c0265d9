// SPDX-License-Identifier: MIT
// What a run prints: to the terminal (unless quiet) and to log.txt. Messages issued before the
// output folder exists are kept and written when log.txt opens, so that bad input leaves no files.
#pragma once

#include <cstdio>
#include <string>

namespace tribex::solver {

class RunLog {
 public:
  explicit RunLog(bool quiet) : quiet_(quiet) {}
  ~RunLog();
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;

  /// Opens log.txt (writing what was said so far); a resumed run appends to the earlier segments' log.
  void open(const std::string& path, bool append = false);
  /// A line to the terminal (stdout) and the log.
  void say(const std::string& line);
  /// A line to the log only (the resolved deck echo).
  void record(const std::string& text);
  bool quiet() const { return quiet_; }

 private:
  bool quiet_;
  std::FILE* file_ = nullptr;
  std::string pending_;
};

/// printf into a std::string.
std::string format(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace tribex::solver
