// SPDX-License-Identifier: MIT
#include "solver/parallel/communicator.hpp"

#include <mpi.h>

#include <vector>

namespace tribex::solver::parallel {
namespace {

bool active() {
  int initialized = 0, finalized = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  return initialized && !finalized;
}

}  // namespace

int rank() {
  if (!active()) return 0;
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int size() {
  if (!active()) return 1;
  int s = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &s);
  return s;
}

void sum(double* values, int count) {
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

void sum(long long* values, int count) {
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
}

double min(double value) {
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  return value;
}

double max(double value) {
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return value;
}

long long max(long long value) {
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
  return value;
}

double min_location(double value, int& payload) {
  if (size() <= 1) return value;
  struct {
    double value;
    int payload;
  } pair{value, payload};
  MPI_Allreduce(MPI_IN_PLACE, &pair, 1, MPI_DOUBLE_INT, MPI_MINLOC, MPI_COMM_WORLD);
  payload = pair.payload;
  return pair.value;
}

void barrier() {
  if (size() > 1) MPI_Barrier(MPI_COMM_WORLD);
}

void broadcast(int* values, int count, int root) {
  if (size() > 1) MPI_Bcast(values, count, MPI_INT, root, MPI_COMM_WORLD);
}

std::string all_gather(const std::string& mine, std::vector<int>& at) {
  const int ranks = size(), n = static_cast<int>(mine.size());
  at.assign(static_cast<std::size_t>(ranks) + 1, 0);
  if (ranks <= 1) {
    at[1] = n;
    return mine;
  }
  std::vector<int> count(static_cast<std::size_t>(ranks));
  MPI_Allgather(&n, 1, MPI_INT, count.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 0; r < ranks; ++r) at[r + 1] = at[r] + count[r];
  std::string all(static_cast<std::size_t>(at[ranks]), '\0');
  MPI_Allgatherv(mine.data(), n, MPI_CHAR, all.data(), count.data(), at.data(), MPI_CHAR, MPI_COMM_WORLD);
  return all;
}

void broadcast(std::string& text, int root) {
  if (size() <= 1) return;
  int n = static_cast<int>(text.size());
  MPI_Bcast(&n, 1, MPI_INT, root, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(n));
  MPI_Bcast(text.data(), n, MPI_CHAR, root, MPI_COMM_WORLD);
}

}  // namespace tribex::solver::parallel
