// SPDX-License-Identifier: MIT
// What one rank held and did in a run (issue 25, scope 3): its elements and nodes, the contact
// faces it holds without owning them, the bytes it exchanged, the contact work it did and its peak
// memory. Every rank fills one from counters kept in the loop by plain increments (Domain::traffic,
// ContactManager::work), rank 0 gathers them at the close (one MPI_Gather of this fixed struct)
// and summary.json writes them as `rank_counts` (keys and units: rank_count_fields() in
// solver/output/output_tables.cpp). They are counts, not times: they show whether memory and
// contact work fall with the rank count.
#pragma once

#include <vector>

namespace tribex::inputs {
struct ContactSpec;
}

namespace tribex::solver {
struct Model;
}

namespace tribex::solver::parallel {

/// All members are long long so that the struct is one MPI_LONG_LONG array (gather_rank_counts).
struct RankCounts {
  long long rank = 0;
  long long elements = 0;      // elements of this rank
  long long nodes = 0;         // nodes held (owned + held by a lower rank too)
  long long owned_nodes = 0;   // nodes this rank owns (shared ones: the lowest holder)
  long long shared_nodes = 0;  // held nodes that other ranks hold too
  long long contact_faces = 0; // contact-surface faces of this rank's contact region (all four nodes held or ghost)
  long long ghost_faces = 0;   // ... of which the element belongs to another rank
  long long halo_exchanges = 0, halo_bytes_sent = 0, halo_bytes_received = 0;
  long long surface_gathers = 0, contact_bytes_sent = 0, contact_bytes_received = 0;
  long long contact_evaluations = 0;  // ContactManager::compute_forces calls
  long long searches = 0, search_reuses = 0, contact_pairs = 0;
  long long peak_rss_setup_bytes = 0;  // getrusage ru_maxrss at the end of set-up
  long long peak_rss_bytes = 0;        // ... at the close
  long long exchange_peers = 0;        // ranks it exchanged values with through sparse_exchange.hpp, itself excluded
};

/// The process's peak resident set size so far (getrusage ru_maxrss), bytes.
long long peak_rss_bytes();

/// This rank's counts from its model at the close. `spec` the deck's contact definition (nullptr:
/// none): a surface face is owned here when its side-set entry is in this rank's part (its element is
/// this rank's); every other face of its contact region is a ghost face.
RankCounts count_rank(const Model& model, const inputs::ContactSpec* spec, long long peak_rss_setup);

/// Every rank's counts on rank 0, in rank order (other ranks: empty). Collective; one rank: {mine}.
std::vector<RankCounts> gather_rank_counts(const RankCounts& mine);

}  // namespace tribex::solver::parallel
