// SPDX-License-Identifier: MIT
// One rank's results.exo.N.r (README.md "Exodus II output").
#include "solver/output/exodus_rank_file.hpp"

#include <exodusII.h>
#include <mpi.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "solver/parallel/communicator.hpp"
#include "solver/parallel/sparse_exchange.hpp"

namespace tribex::solver::output {
namespace {

// Every rank's names, joined: each rank sends its names as one '\n'-separated text.
std::set<std::string> names_of_all_ranks(const std::vector<std::string>& mine) {
  std::string text;
  for (const auto& n : mine) text += n + '\n';
  std::vector<int> at;
  const std::string all = parallel::all_gather(text, at);
  std::set<std::string> names;
  for (std::size_t start = 0, end; (end = all.find('\n', start)) != std::string::npos; start = end + 1)
    names.insert(all.substr(start, end - start));
  return names;
}

template <class Map>
std::vector<std::string> keys(const Map& m) {
  std::vector<std::string> k;
  for (const auto& [name, v] : m) k.push_back(name);
  return k;
}

}  // namespace

std::string rank_file_name(int ranks, int rank) {
  const std::string n = std::to_string(ranks);
  std::string r = std::to_string(rank);
  r.insert(0, n.size() - std::min(n.size(), r.size()), '0');
  return "results.exo." + n + "." + r;
}

mesh::Mesh rank_file_mesh(const mesh::Mesh& local, const MeshOutline& outline) {
  mesh::Mesh m;
  m.coordinates = local.coordinates;
  m.connectivity = local.connectivity;
  // The whole mesh's non-empty blocks in its element order (the serial file's ids 1..B). The rank's
  // elements are in ascending global order, so each block's are one contiguous run of local elements.
  std::vector<mesh::Block> global;
  for (const auto& b : outline.blocks)
    if (b.element_count > 0) global.push_back(b);
  std::stable_sort(global.begin(), global.end(), [](const auto& a, const auto& b) { return a.first_element < b.first_element; });
  int next = 0;
  for (const auto& g : global) {
    const auto it = std::find_if(local.blocks.begin(), local.blocks.end(), [&](const auto& b) { return b.name == g.name; });
    const int count = it == local.blocks.end() ? 0 : it->element_count;
    if (count > 0 && it->first_element != next)
      throw std::logic_error("rank_file_mesh: block '" + g.name + "' is not in the whole mesh's block order here");
    m.blocks.push_back({g.name, next, count});
    next += count;
  }
  if (next != local.element_count()) throw std::logic_error("rank_file_mesh: a local block is not in the outline");
  m.node_sets = local.node_sets;
  m.side_sets = local.side_sets;
  for (const auto& n : names_of_all_ranks(keys(local.node_sets))) m.node_sets[n];  // empty where the rank has none
  for (const auto& n : names_of_all_ranks(keys(local.side_sets))) m.side_sets[n];
  return m;
}

RankGlobals rank_globals(const mesh::Mesh& file_mesh, const parallel::Domain& domain) {
  RankGlobals g;
  for (const auto& b : file_mesh.blocks) g.block_counts.push_back(b.element_count);
  // A node set's members counted once (by their owner); a side set's sides are per element, on one rank each.
  for (const auto& [name, nodes] : file_mesh.node_sets) {
    int owned = 0;
    for (int n : nodes) owned += domain.owned[static_cast<std::size_t>(n)] != 0.0;
    g.node_set_sizes.push_back(owned);
  }
  for (const auto& [name, sides] : file_mesh.side_sets) g.side_set_sizes.push_back(static_cast<int>(sides.size()));
  for (auto* v : {&g.block_counts, &g.node_set_sizes, &g.side_set_sizes})
    MPI_Allreduce(MPI_IN_PLACE, v->data(), static_cast<int>(v->size()), MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  return g;
}

int put_rank_maps(int exo, const mesh::Mesh& file_mesh, const parallel::Domain& domain, const MeshOutline& outline,
                  const RankGlobals& globals) {
  // Number maps: what ParaView's readers and a join stitch the files by (global index + 1).
  std::vector<int> node_map(domain.global_node.size()), element_map(domain.global_element.size());
  for (std::size_t i = 0; i < node_map.size(); ++i) node_map[i] = domain.global_node[i] + 1;
  for (std::size_t i = 0; i < element_map.size(); ++i) element_map[i] = domain.global_element[i] + 1;
  if (ex_put_id_map(exo, EX_NODE_MAP, node_map.data()) < 0) return -1;
  if (ex_put_id_map(exo, EX_ELEM_MAP, element_map.data()) < 0) return -1;

  // Nemesis I: the whole mesh's counts, this file's place among them, and the shared nodes.
  const auto blocks = static_cast<int>(file_mesh.blocks.size());
  const auto node_sets = static_cast<int>(file_mesh.node_sets.size()), side_sets = static_cast<int>(file_mesh.side_sets.size());
  char spread[] = "p";  // parallel (one file per rank), not "s" (scalar: one file of all ranks)
  if (ex_put_init_info(exo, domain.ranks, 1, spread) < 0) return -1;
  if (ex_put_init_global(exo, outline.nodes, outline.elements, blocks, node_sets, side_sets) < 0) return -1;
  const auto ids = [](int n) {
    std::vector<int> v(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) v[k] = k + 1;
    return v;
  };
  auto g = globals;  // the API takes non-const pointers; it only reads
  std::vector<int> zeros(static_cast<std::size_t>(std::max(node_sets, side_sets)), 0), id;
  if (blocks > 0 && ex_put_eb_info_global(exo, (id = ids(blocks)).data(), g.block_counts.data()) < 0) return -1;
  if (node_sets > 0 && ex_put_ns_param_global(exo, (id = ids(node_sets)).data(), g.node_set_sizes.data(), zeros.data()) < 0)
    return -1;
  if (side_sets > 0 && ex_put_ss_param_global(exo, (id = ids(side_sets)).data(), g.side_set_sizes.data(), zeros.data()) < 0)
    return -1;

  // Internal nodes (held by this rank alone) and border nodes (shared), local numbers + 1; one node
  // communication map per neighbour rank: the shared nodes and the rank they are shared with.
  std::vector<int> internal, border, cmap_nodes, cmap_procs, map_ids, map_counts;
  for (int l = 0; l < static_cast<int>(domain.global_node.size()); ++l) {
    bool shared = false;
    for (int r = 0; r < domain.ranks; ++r)
      if (r != domain.rank && domain.shares_with(l, r)) {
        shared = true;
        break;
      }
    (shared ? border : internal).push_back(l + 1);
  }
  for (int r = 0; r < domain.ranks; ++r) {
    if (r == domain.rank) continue;
    int count = 0;
    for (int b : border)
      if (domain.shares_with(b - 1, r)) {
        cmap_nodes.push_back(b);
        cmap_procs.push_back(r);
        ++count;
      }
    if (count > 0) {
      map_ids.push_back(r + 1);
      map_counts.push_back(count);
    }
  }
  std::vector<int> elements(file_mesh.connectivity.size() / 8);
  for (std::size_t e = 0; e < elements.size(); ++e) elements[e] = static_cast<int>(e) + 1;
  if (ex_put_loadbal_param(exo, static_cast<int64_t>(internal.size()), static_cast<int64_t>(border.size()), 0,
                           static_cast<int64_t>(elements.size()), 0, static_cast<int64_t>(map_ids.size()), 0,
                           domain.rank) < 0)
    return -1;
  if (ex_put_processor_node_maps(exo, internal.data(), border.data(), nullptr, domain.rank) < 0) return -1;
  if (ex_put_processor_elem_maps(exo, elements.data(), nullptr, domain.rank) < 0) return -1;
  if (!map_ids.empty()) {
    if (ex_put_cmap_params(exo, map_ids.data(), map_counts.data(), nullptr, nullptr, domain.rank) < 0) return -1;
    std::size_t at = 0;
    for (std::size_t k = 0; k < map_ids.size(); ++k) {
      if (ex_put_node_cmap(exo, map_ids[k], cmap_nodes.data() + at, cmap_procs.data() + at, domain.rank) < 0) return -1;
      at += static_cast<std::size_t>(map_counts[k]);
    }
  }
  return ex_update(exo);
}

SharedNodeRows::SharedNodeRows(const parallel::Domain& domain)
    : local_nodes_(static_cast<int>(domain.global_node.size())), owned_local_(domain.owned_local_nodes()) {
  // A node not owned here is owned by the lowest rank holding it (domain.hpp): ask that rank for it.
  const int ranks = domain.ranks;
  std::vector<std::vector<int>> asked(static_cast<std::size_t>(ranks));  // global nodes, per owner
  for (int l = 0; l < local_nodes_; ++l) {
    if (domain.owned[static_cast<std::size_t>(l)] != 0.0) continue;
    int owner = 0;
    while (owner < domain.rank && !domain.shares_with(l, owner)) ++owner;
    asked[static_cast<std::size_t>(owner)].push_back(l);
  }
  receive_counts_.assign(static_cast<std::size_t>(ranks), 0);
  receive_displs_.assign(receive_counts_.size(), 0);
  std::vector<int> asked_global;
  for (int r = 0; r < ranks; ++r) {
    receive_counts_[r] = static_cast<int>(asked[r].size());
    if (r > 0) receive_displs_[r] = receive_displs_[r - 1] + receive_counts_[r - 1];
    for (int l : asked[r]) {
      receive_local_.push_back(l);
      asked_global.push_back(domain.global_node[static_cast<std::size_t>(l)]);
    }
  }
  send_counts_ = parallel::sparse_counts(receive_counts_);
  send_displs_.assign(receive_counts_.size(), 0);
  for (int r = 1; r < ranks; ++r) send_displs_[r] = send_displs_[r - 1] + send_counts_[r - 1];
  std::vector<int> wanted(static_cast<std::size_t>(send_displs_.back() + send_counts_.back()));
  parallel::sparse_alltoallv(asked_global.data(), receive_counts_.data(), receive_displs_.data(), wanted.data(),
                             send_counts_.data(), send_displs_.data(), MPI_INT);
  std::vector<int> row_of_local(static_cast<std::size_t>(local_nodes_), -1);
  for (std::size_t k = 0; k < owned_local_.size(); ++k) row_of_local[static_cast<std::size_t>(owned_local_[k])] = static_cast<int>(k);
  for (int g : wanted) {
    const int l = domain.local_node(g);
    const int row = l < 0 ? -1 : row_of_local[static_cast<std::size_t>(l)];
    if (row < 0) throw std::logic_error("SharedNodeRows: a rank asked for a node this rank does not own");
    send_row_.push_back(row);
  }
}

void SharedNodeRows::fill(const double* owned_rows, int components, std::vector<double>& local) {
  const auto c = static_cast<std::size_t>(components);
  local.resize(c * static_cast<std::size_t>(local_nodes_));
  for (std::size_t k = 0; k < owned_local_.size(); ++k)
    std::copy_n(owned_rows + c * k, c, local.data() + c * static_cast<std::size_t>(owned_local_[k]));
  send_.resize(c * send_row_.size());
  for (std::size_t k = 0; k < send_row_.size(); ++k)
    std::copy_n(owned_rows + c * static_cast<std::size_t>(send_row_[k]), c, send_.data() + c * k);
  receive_.resize(c * receive_local_.size());
  const auto scaled = [&](const std::vector<int>& in, std::vector<int>& out) {
    out.resize(in.size());
    for (std::size_t r = 0; r < in.size(); ++r) out[r] = in[r] * components;
  };
  scaled(send_counts_, counts_);
  scaled(send_displs_, displs_);
  scaled(receive_counts_, rcounts_);
  scaled(receive_displs_, rdispls_);
  parallel::sparse_alltoallv(send_.data(), counts_.data(), displs_.data(), receive_.data(), rcounts_.data(),
                             rdispls_.data(), MPI_DOUBLE);
  for (std::size_t k = 0; k < receive_local_.size(); ++k)
    std::copy_n(receive_.data() + c * k, c, local.data() + c * static_cast<std::size_t>(receive_local_[k]));
}

}  // namespace tribex::solver::output
