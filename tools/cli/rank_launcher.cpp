// SPDX-License-Identifier: MIT
#include "tools/cli/rank_launcher.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "solver/run/stop_signal.hpp"
#include "tools/common/errors.hpp"

namespace tribex::cli {
namespace {

// The directories of PATH that hold an executable `name`, first match.
std::string on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t start = 0; start <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string candidate = (end > start ? dirs.substr(start, end - start) : ".") + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    start = end + 1;
  }
  return {};
}

bool allowed_as_root() {
  return std::getenv("OMPI_ALLOW_RUN_AS_ROOT") && std::getenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM");
}

[[noreturn]] void exec_mpirun(const std::vector<std::string>& command) {
  ::setpgid(0, 0);  // its own group: a terminal's Ctrl-C goes to the launcher, which forwards SIGUSR1
  const int null = ::open("/dev/null", O_RDONLY);
  if (null >= 0) ::dup2(null, STDIN_FILENO);  // mpirun forwards stdin; from another group it would stop on the tty
  for (int s : {SIGINT, SIGTERM, SIGUSR1, SIGCONT}) ::signal(s, SIG_DFL);
  std::vector<char*> argv;
  for (const auto& a : command) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  ::execv(argv[0], argv.data());
  _exit(127);
}

}  // namespace

std::vector<std::string> without_ranks_option(const std::vector<std::string>& args) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (args[k] == "--ranks") {
      ++k;
      continue;
    }
    if (args[k].rfind("--ranks=", 0) == 0) continue;
    out.push_back(args[k]);
  }
  return out;
}

int run_under_mpirun(int ranks, const std::vector<std::string>& run_args) {
  const std::string mpirun = on_path("mpirun");
  if (mpirun.empty())
    throw tools::BadInput("tribex run: --ranks needs Open MPI's mpirun on PATH; apt-get install openmpi-bin, or run "
                          "without --ranks (one rank)");
  if (::geteuid() == 0 && !allowed_as_root())
    throw tools::BadInput("tribex run: --ranks as root: mpirun refuses to start as root; run as a user, or set "
                          "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 to allow it");
  std::vector<std::string> command = {mpirun, "-np", std::to_string(ranks)};
  if (static_cast<unsigned>(ranks) > std::thread::hardware_concurrency()) command.push_back("--oversubscribe");
  std::error_code ec;
  command.push_back(std::filesystem::read_symlink("/proc/self/exe", ec).string());
  command.push_back("run");
  command.insert(command.end(), run_args.begin(), run_args.end());
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw tools::BadInput(std::string("tribex run: --ranks: cannot start mpirun (fork failed)"));
  if (pid == 0) exec_mpirun(command);
  // The stop handlers (installed by main for `run`) record a signal; forward the first one once.
  bool forwarded = false;
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) return 1;
    if (!forwarded && solver::stop_signal() != 0) {
      ::kill(pid, SIGUSR1);
      forwarded = true;
    }
    ::usleep(20000);
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + WTERMSIG(status);
}

}  // namespace tribex::cli
