// SPDX-License-Identifier: MIT
#include "solver/parallel/rank_counts.hpp"

#include <mpi.h>
#include <sys/resource.h>

#include <type_traits>

#include "inputs/deck.hpp"
#include "solver/model.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/sparse_exchange.hpp"

namespace tribex::solver::parallel {

static_assert(std::is_standard_layout_v<RankCounts> && sizeof(RankCounts) % sizeof(long long) == 0,
              "RankCounts travels as an array of long long");

long long peak_rss_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0;
  return 1024LL * u.ru_maxrss;  // Linux: KiB
}

RankCounts count_rank(const Model& model, const inputs::ContactSpec* spec, long long peak_rss_setup) {
  const Domain& d = model.domain;
  RankCounts c;
  c.rank = d.rank;
  c.elements = static_cast<long long>(d.global_element.size());
  c.nodes = static_cast<long long>(d.global_node.size());
  c.owned_nodes = d.owned_node_count();
  c.shared_nodes = d.shared_node_count();
  c.halo_exchanges = d.traffic.halo_exchanges;
  c.halo_bytes_sent = d.traffic.halo_sent;
  c.halo_bytes_received = d.traffic.halo_received;
  c.surface_gathers = d.traffic.surface_gathers;
  c.contact_bytes_sent = d.traffic.surface_sent;
  c.contact_bytes_received = d.traffic.surface_received;
  if (model.contact) {
    // The faces of this rank's contact region (every face on one rank).
    c.contact_faces = model.contact->present_face_count();
    long long own = 0;
    if (spec)
      for (const auto& s : spec->surfaces)
        for (const auto& set : s.side_sets)
          if (auto it = model.mesh.side_sets.find(set); it != model.mesh.side_sets.end())
            own += static_cast<long long>(it->second.size());
    c.ghost_faces = spec ? c.contact_faces - own : 0;
    const auto& w = model.contact->work();
    c.contact_evaluations = w.calls;
    c.searches = w.searches;
    c.search_reuses = w.reuses;
    c.contact_pairs = w.pairs;
  }
  c.peak_rss_setup_bytes = peak_rss_setup;
  c.peak_rss_bytes = peak_rss_bytes();
  c.exchange_peers = sparse_exchange_peers();
  return c;
}

std::vector<RankCounts> gather_rank_counts(const RankCounts& mine) {
  const int n = size();
  if (n == 1) return {mine};
  constexpr int values = static_cast<int>(sizeof(RankCounts) / sizeof(long long));
  std::vector<RankCounts> all(is_root() ? static_cast<std::size_t>(n) : 0);
  MPI_Gather(&mine, values, MPI_LONG_LONG, all.data(), values, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  return all;
}

}  // namespace tribex::solver::parallel
