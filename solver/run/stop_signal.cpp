// SPDX-License-Identifier: MIT
#include "solver/run/stop_signal.hpp"

#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>

namespace tribex::solver {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;
volatile std::sig_atomic_t g_job_control_stop = 0;  // a SIGTSTP stopped us: the next SIGCONT resumes
timespec g_stop_time{};                              // CLOCK_MONOTONIC at the first stop (written once)

void record_stop(int sig) {
  if (g_stop_signal != 0) return;
  clock_gettime(CLOCK_MONOTONIC, &g_stop_time);  // async-signal-safe
  g_stop_signal = sig;
}

// The first stop is kept (a later SIGTERM of mpirun's kill sequence does not hide its SIGCONT).
extern "C" void on_stop_signal(int sig) { record_stop(sig); }

void install(int sig, void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // a write or read in progress completes instead of failing with EINTR
  sigaction(sig, &action, nullptr);
}

// SIGTSTP (Ctrl-Z, forwarded by mpirun): remembered, then the default stop; the resume's SIGCONT
// (which runs while this handler waits) is then job control, not mpirun's kill sequence.
extern "C" void on_job_control_stop(int) {
  const int saved = errno;
  g_job_control_stop = 1;
  install(SIGTSTP, SIG_DFL);
  sigset_t tstp;
  sigemptyset(&tstp);
  sigaddset(&tstp, SIGTSTP);
  sigprocmask(SIG_UNBLOCK, &tstp, nullptr);
  raise(SIGTSTP);  // stops here until SIGCONT
  install(SIGTSTP, on_job_control_stop);
  errno = saved;
}

extern "C" void on_continue(int, siginfo_t* info, void*) {
  if (g_job_control_stop) {
    g_job_control_stop = 0;
    return;
  }
  // Sent by the launcher that started us (mpirun, or orted on another node): mpirun is ending the job.
  if (info && info->si_code == SI_USER && info->si_pid == getppid()) record_stop(SIGCONT);
}

}  // namespace

void install_stop_handlers(bool under_mpirun) {
  install(SIGINT, on_stop_signal);
  install(SIGTERM, on_stop_signal);
  install(SIGUSR1, on_stop_signal);
  if (!under_mpirun) return;
  install(SIGTSTP, on_job_control_stop);
  struct sigaction action {};
  action.sa_sigaction = on_continue;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART | SA_SIGINFO;
  sigaction(SIGCONT, &action, nullptr);
}

int stop_signal() { return g_stop_signal; }

double seconds_since_stop_signal() {
  if (g_stop_signal == 0) return 0.0;
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return double(now.tv_sec - g_stop_time.tv_sec) + 1e-9 * double(now.tv_nsec - g_stop_time.tv_nsec);
}

std::string stop_signal_text(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGUSR1: return "SIGUSR1";
    case SIGCONT: return "SIGCONT from mpirun (the start of its kill sequence after a SIGTERM or SIGINT)";
    default: return "signal " + std::to_string(signal);
  }
}

void fault_signal_point(const char* point) {
  const char* at = std::getenv("TRIBEX_FAULT_SIGNAL");
  if (at && std::strcmp(at, point) == 0) std::raise(SIGTERM);
}

}  // namespace tribex::solver
