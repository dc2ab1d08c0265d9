// SPDX-License-Identifier: MIT
// Times the writing of one restart file on N ranks (issue 57 scope 3; figures in
// docs/measurements/2026-11-29-parallel-restart.md). Each rank takes its own group of a restart file a
// run on N ranks wrote (the run's real archive: entry names and sizes), then writes the whole file
// REPEATS times with write_restart_file into OUT_DIR, a barrier before each. Prints per write the
// slowest rank's time, then the median and the minimum. Built by hand against a build's libraries, so
// that the same source times the writer of any commit (the command: tools/bench/README.md, "Restart").
//
//   mpirun -np N restart_write_bench RESTART_FILE OUT_DIR [REPEATS]
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "solver/restart/state_archive.hpp"

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (argc < 3) {
    if (rank == 0) std::fprintf(stderr, "usage: restart_write_bench RESTART_FILE OUT_DIR [REPEATS]\n");
    MPI_Finalize();
    return 2;
  }
  const int repeats = argc > 3 ? std::atoi(argv[3]) : 5;
  tribex::solver::StateArchive archive;
  {
    const tribex::solver::RestartFile file(argv[1]);
    if (file.ranks() != ranks && rank == 0)
      std::fprintf(stderr, "note: %s was written by %d ranks; rank r takes group r %% %d\n", argv[1], file.ranks(), file.ranks());
    archive = file.read_group(rank % file.ranks());
  }
  long long values = 0;
  for (const auto& [name, v] : archive.reals) values += static_cast<long long>(v.size());
  for (const auto& [name, v] : archive.integers) values += static_cast<long long>(v.size());
  MPI_Allreduce(MPI_IN_PLACE, &values, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  const std::string out = (std::filesystem::path(argv[2]) / "restart_bench.h5").string();
  std::vector<double> times;
  for (int k = 0; k <= repeats; ++k) {  // k = 0: a warm-up write, not counted
    MPI_Barrier(MPI_COMM_WORLD);
    const double t0 = MPI_Wtime();
    tribex::solver::write_restart_file(out, archive, "bench");
    double t = MPI_Wtime() - t0;
    MPI_Allreduce(MPI_IN_PLACE, &t, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    if (k > 0) times.push_back(t);
  }
  if (rank == 0) {
    std::sort(times.begin(), times.end());
    std::printf("ranks=%d entries_rank0=%zu values=%lld file_bytes=%llu median_s=%.4f min_s=%.4f max_s=%.4f\n", ranks,
                archive.reals.size() + archive.integers.size(), values,
                static_cast<unsigned long long>(std::filesystem::file_size(out)), times[times.size() / 2], times.front(),
                times.back());
  }
  MPI_Finalize();
  return 0;
}
