// SPDX-License-Identifier: MIT
#include "solver/output/run_log.hpp"

#include <cerrno>
#include <cstdarg>
#include <cstring>

#include "solver/errors.hpp"

namespace tribex::solver {

std::string format(const char* fmt, ...) {
  va_list args;
  va_start(args, fmt);
  char buf[1024];
  const int n = std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  if (n < static_cast<int>(sizeof buf)) return buf;
  std::string big(static_cast<std::size_t>(n) + 1, '\0');
  va_start(args, fmt);
  std::vsnprintf(big.data(), big.size(), fmt, args);
  va_end(args);
  big.resize(static_cast<std::size_t>(n));
  return big;
}

RunLog::~RunLog() {
  if (file_) std::fclose(file_);
}

void RunLog::open(const std::string& path, bool append) {
  file_ = std::fopen(path.c_str(), append ? "a" : "w");
  if (!file_) throw SetupError("cannot write " + path + ": " + std::strerror(errno));
  std::fputs(pending_.c_str(), file_);
  // A log that cannot take what was said so far (a full disk) fails the set-up, naming the cause.
  if (std::fflush(file_) != 0 || std::ferror(file_)) throw output_failure(path, errno);
  pending_.clear();
}

void RunLog::say(const std::string& line) {
  if (!quiet_) {
    std::fputs(line.c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
  }
  record(line + "\n");
}

void RunLog::record(const std::string& text) {
  if (file_) {
    std::fputs(text.c_str(), file_);
    std::fflush(file_);
  } else {
    pending_ += text;
  }
}

}  // namespace tribex::solver
