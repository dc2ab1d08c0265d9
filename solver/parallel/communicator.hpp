// SPDX-License-Identifier: MIT
// The run's ranks (MPI_COMM_WORLD). Every helper works without MPI_Init (unit tests, tools that
// never start MPI): it is then one rank and the collectives return their input. The serial run is
// the one-rank case of the same code path.
#pragma once

#include <string>
#include <vector>

namespace tribex::solver::parallel {

int rank();
int size();
inline bool is_root() { return rank() == 0; }

/// Global reductions (in place). No-ops on one rank.
void sum(double* values, int count);
void sum(long long* values, int count);
double min(double value);
double max(double value);
long long max(long long value);
/// Minimum over ranks; `payload` becomes the smallest payload among the ranks holding the minimum.
double min_location(double value, int& payload);
void barrier();
/// Broadcast from `root`.
void broadcast(int* values, int count, int root = 0);
void broadcast(std::string& text, int root);
/// Every rank's `mine` joined in rank order, on every rank; `at` gets the ranks + 1 offsets of each rank's bytes.
std::string all_gather(const std::string& mine, std::vector<int>& at);

}  // namespace tribex::solver::parallel
