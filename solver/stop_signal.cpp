// SPDX-License-Identifier: MIT
#include "solver/stop_signal.hpp"

#include <csignal>
#include <cstdlib>
#include <cstring>

namespace tribex::solver {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void on_stop_signal(int sig) { g_stop_signal = sig; }

}  // namespace

void install_stop_handlers() {
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a write or read in progress completes instead of failing with EINTR
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int stop_signal() { return g_stop_signal; }

void fault_signal_point(const char* point) {
  const char* at = std::getenv("TRIBEX_FAULT_SIGNAL");
  if (at && std::strcmp(at, point) == 0) std::raise(SIGTERM);
}

}  // namespace tribex::solver
