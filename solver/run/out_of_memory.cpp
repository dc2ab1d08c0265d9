// SPDX-License-Identifier: MIT
#include "solver/run/out_of_memory.hpp"

#include <sys/resource.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "solver/output/run_log.hpp"

namespace tribex::solver {
namespace {

std::atomic<std::size_t> g_failed_request{0};

std::string bytes_text(double b) {
  if (b >= 1e9) return format("%.3g GB", b / 1e9);
  if (b >= 1e6) return format("%.3g MB", b / 1e6);
  return format("%.0f bytes", b);
}

}  // namespace

void record_failed_allocation(std::size_t n) { g_failed_request.store(n); }

std::size_t last_failed_allocation() { return g_failed_request.load(); }

std::string out_of_memory_text(const std::string& stage) {
  std::string detail;
  if (const std::size_t n = last_failed_allocation()) detail = "a request for " + bytes_text(double(n)) + " failed";
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    detail += (detail.empty() ? "" : "; ") + std::string("address-space limit ") + bytes_text(double(limit.rlim_cur)) +
              " (ulimit -v)";
  return "out of memory while " + stage + (detail.empty() ? "" : " (" + detail + ")");
}

}  // namespace tribex::solver

