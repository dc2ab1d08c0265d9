// SPDX-License-Identifier: MIT
// How long Open MPI's mpirun lets the ranks stop after it is sent SIGTERM or SIGINT, and the note that
// says when a run needs longer (log.txt; docs/architecture.md "Signals"). mpirun 4.1 sends each rank
// SIGCONT, then SIGTERM odls_base_sigkill_timeout seconds later (1 by default), then SIGKILL as long
// again; the ranks stop at SIGCONT (solver/run/stop_signal.hpp), so they have twice the timeout.
#pragma once

#include <string>

namespace tribex::solver {

/// Seconds of stop time per element, used before a run has measured its own: the step that is
/// running, its outputs, the restart file and the close. Measured on the 2-core CI machine under load
/// (2 ranks, the wave deck of tests/parallel/mpi_wave.i refined, displacement, velocity and stress
/// every picosecond): 512,000 elements 2.4 s, 216,000 elements 1.0 s, about 5 us each; 8 us leaves
/// room for a slower disk.
inline constexpr double stop_seconds_per_element = 8e-6;

/// 2 x OMPI_MCA_odls_base_sigkill_timeout (1 when unset) for a rank started by Open MPI's mpirun
/// (OMPI_COMM_WORLD_SIZE in the environment); infinity otherwise (no one will SIGKILL the run).
double mpirun_stop_grace_seconds();

/// The note for log.txt when `needed` seconds (the stop's time, `basis` says how it was found) is
/// over half of mpirun's grace; empty when the grace is enough. It names the setting, with a value
/// that gives at least 4 x `needed`, and SIGUSR1 (forwarded at once, no time limit).
std::string mpirun_stop_grace_note(double needed, const std::string& basis);

}  // namespace tribex::solver
