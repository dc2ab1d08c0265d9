// SPDX-License-Identifier: MIT
#include "solver/run/mpirun_grace.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>

#include "solver/output/run_log.hpp"

namespace tribex::solver {

double mpirun_stop_grace_seconds() {
  if (std::getenv("OMPI_COMM_WORLD_SIZE") == nullptr) return std::numeric_limits<double>::infinity();
  const char* timeout = std::getenv("OMPI_MCA_odls_base_sigkill_timeout");
  const int seconds = timeout ? std::atoi(timeout) : 1;
  return 2.0 * (seconds > 0 ? seconds : 0);
}

std::string mpirun_stop_grace_note(double needed, const std::string& basis) {
  const double grace = mpirun_stop_grace_seconds();
  if (!(needed > 0.5 * grace)) return {};
  const int timeout = static_cast<int>(std::ceil(2.0 * needed));  // a grace of 2 x timeout >= 4 x needed
  return format("note: after a SIGTERM or SIGINT to mpirun, Open MPI kills the ranks %g s later (2 x "
                "odls_base_sigkill_timeout) and this run needs about %.3g s to stop (%s): start mpirun with "
                "OMPI_MCA_odls_base_sigkill_timeout=%d in the environment, or stop the run with SIGUSR1 to mpirun "
                "(forwarded at once, no time limit), or start it with tribex run --ranks N, which forwards a "
                "SIGTERM or SIGINT to it as SIGUSR1",
                grace, needed, basis.c_str(), timeout < 1 ? 1 : timeout);
}

}  // namespace tribex::solver
