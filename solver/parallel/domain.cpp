// SPDX-License-Identifier: MIT
#include "solver/parallel/domain.hpp"

#include <algorithm>
#include <chrono>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "solver/model.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver::parallel {

void Domain::init_serial(int nodes, int elements) {
  rank = 0;
  ranks = 1;
  global_node_count = nodes;
  global_element_count = elements;
  global_node.resize(static_cast<std::size_t>(nodes));
  std::iota(global_node.begin(), global_node.end(), 0);
  global_element.resize(static_cast<std::size_t>(elements));
  std::iota(global_element.begin(), global_element.end(), 0);
  owned.assign(static_cast<std::size_t>(nodes), 1.0);
  owned_nodes_ = nodes;
  owned_local_nodes_ = global_node;
  node_owner_.assign(static_cast<std::size_t>(nodes), 0);
}

namespace {
double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }
}  // namespace

void Domain::sum_shared(double* f) {
  if (neighbours_.empty()) return;
  const double start = now();
  const int nk = static_cast<int>(neighbours_.size());
  ++traffic.halo_exchanges;
  for (int k = 0; k < nk; ++k) {
    const int b = neighbour_offset_[k], n = neighbour_offset_[k + 1] - b;
    MPI_Irecv(&recv_[3 * b], 3 * n, MPI_DOUBLE, neighbours_[k], 17, MPI_COMM_WORLD, &requests_[k]);
    traffic.halo_received += static_cast<long long>(sizeof(double)) * 3 * n;
  }
  for (int k = 0; k < nk; ++k) {
    const int b = neighbour_offset_[k], n = neighbour_offset_[k + 1] - b;
    for (int j = b; j < b + n; ++j)
      for (int i = 0; i < 3; ++i) send_[3 * j + i] = f[3 * neighbour_nodes_[j] + i];
    MPI_Isend(&send_[3 * b], 3 * n, MPI_DOUBLE, neighbours_[k], 17, MPI_COMM_WORLD, &requests_[nk + k]);
    traffic.halo_sent += static_cast<long long>(sizeof(double)) * 3 * n;
  }
  MPI_Waitall(2 * nk, requests_.data(), MPI_STATUSES_IGNORE);
  // Sum in ascending rank order (0 + f_r1 + f_r2 + ...): the same operations on every rank that
  // holds the node, so all copies stay bit-identical.
  std::fill(sum_.begin(), sum_.end(), 0.0);
  bool mine_added = false;
  auto add_mine = [&]() {
    for (std::size_t s = 0; s < shared_nodes_.size(); ++s)
      for (int i = 0; i < 3; ++i) sum_[3 * s + i] += f[3 * shared_nodes_[s] + i];
    mine_added = true;
  };
  for (int k = 0; k < nk; ++k) {
    if (!mine_added && neighbours_[k] > rank) add_mine();
    for (int j = neighbour_offset_[k]; j < neighbour_offset_[k + 1]; ++j)
      for (int i = 0; i < 3; ++i) sum_[3 * neighbour_slot_[j] + i] += recv_[3 * j + i];
  }
  if (!mine_added) add_mine();
  for (std::size_t s = 0; s < shared_nodes_.size(); ++s)
    for (int i = 0; i < 3; ++i) f[3 * shared_nodes_[s] + i] = sum_[3 * s + i];
  communication_seconds += now() - start;
}

void Domain::set_surface(const std::vector<int>& surface_nodes) {
  surface_nodes_ = surface_nodes;
  const std::size_t ns = surface_nodes.size();
  surface_local_.assign(ns, -1);
  surface_owned_.assign(ns, 0.0);
  surface_send_index_.clear();
  // local index of a global node: global_node is ascending
  for (std::size_t k = 0; k < ns; ++k) {
    auto it = std::lower_bound(global_node.begin(), global_node.end(), surface_nodes[k]);
    if (it != global_node.end() && *it == surface_nodes[k]) {
      const int l = static_cast<int>(it - global_node.begin());
      surface_local_[k] = l;
      surface_owned_[k] = owned[l];
      if (owned[l] > 0.0) surface_send_index_.push_back(l);
    }
  }
  surface_counts_.assign(static_cast<std::size_t>(ranks), 0);
  std::vector<std::vector<int>> by_rank(static_cast<std::size_t>(ranks));
  for (std::size_t k = 0; k < ns; ++k) by_rank[node_owner_[surface_nodes[k]]].push_back(static_cast<int>(k));
  surface_order_.clear();
  surface_displs_.assign(static_cast<std::size_t>(ranks), 0);
  for (int r = 0; r < ranks; ++r) {
    surface_displs_[r] = kSurfaceValues * static_cast<int>(surface_order_.size());
    surface_counts_[r] = kSurfaceValues * static_cast<int>(by_rank[r].size());
    surface_order_.insert(surface_order_.end(), by_rank[r].begin(), by_rank[r].end());
  }
  if (static_cast<int>(by_rank[rank].size()) != static_cast<int>(surface_send_index_.size()))
    throw std::logic_error("surface ownership disagrees between ranks");
  surface_send_.assign(kSurfaceValues * surface_send_index_.size(), 0.0);
  surface_recv_.assign(kSurfaceValues * ns, 0.0);
}

void Domain::gather_surface(const double* x, const double* v, const double* f, double* xg, double* vg, double* fg) {
  if (serial()) {
    for (int node : surface_nodes_)
      for (int i = 0; i < 3; ++i) {
        xg[3 * node + i] = x[3 * node + i];
        vg[3 * node + i] = v[3 * node + i];
        fg[3 * node + i] = f[3 * node + i];
      }
    return;
  }
  const double start = now();
  constexpr int K = kSurfaceValues;
  for (std::size_t j = 0; j < surface_send_index_.size(); ++j) {
    const int l = surface_send_index_[j];
    for (int i = 0; i < 3; ++i) {
      surface_send_[K * j + i] = x[3 * l + i];
      surface_send_[K * j + 3 + i] = v[3 * l + i];
      surface_send_[K * j + 6 + i] = f[3 * l + i];
    }
  }
  MPI_Allgatherv(surface_send_.data(), static_cast<int>(surface_send_.size()), MPI_DOUBLE, surface_recv_.data(),
                 surface_counts_.data(), surface_displs_.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  ++traffic.surface_gathers;
  const long long mine = static_cast<long long>(sizeof(double) * surface_send_.size());
  traffic.surface_sent += mine * (ranks - 1);
  traffic.surface_received += static_cast<long long>(sizeof(double) * surface_recv_.size()) - mine;
  for (std::size_t j = 0; j < surface_order_.size(); ++j) {
    const int node = surface_nodes_[surface_order_[j]];
    for (int i = 0; i < 3; ++i) {
      xg[3 * node + i] = surface_recv_[K * j + i];
      vg[3 * node + i] = surface_recv_[K * j + 3 + i];
      fg[3 * node + i] = surface_recv_[K * j + 6 + i];
    }
  }
  communication_seconds += now() - start;
}

Model localize(Model&& global, const std::vector<int>& part) {
  const int me = parallel::rank(), ranks = parallel::size();
  const mesh::Mesh& gm = global.mesh;
  const int gn = gm.node_count(), ge = gm.element_count();
  global.domain.init_serial(gn, ge);
  if (ranks == 1) return std::move(global);

  Model local;
  Domain& d = local.domain;
  d.rank = me;
  d.ranks = ranks;
  d.global_node_count = gn;
  d.global_element_count = ge;

  // Which ranks hold each node: (node, rank) pairs from the connectivity.
  std::vector<std::pair<int, int>> holders;
  holders.reserve(8 * static_cast<std::size_t>(ge));
  for (int e = 0; e < ge; ++e)
    for (int I = 0; I < 8; ++I) holders.emplace_back(gm.connectivity[8 * e + I], part[e]);
  std::sort(holders.begin(), holders.end());
  holders.erase(std::unique(holders.begin(), holders.end()), holders.end());
  d.node_owner_.assign(static_cast<std::size_t>(gn), -1);
  for (const auto& [node, r] : holders)
    if (d.node_owner_[node] < 0) d.node_owner_[node] = r;  // sorted: the first holder is the lowest rank

  // Local elements and nodes, both ascending in global numbering.
  for (int e = 0; e < ge; ++e)
    if (part[e] == me) d.global_element.push_back(e);
  std::vector<int> local_of(static_cast<std::size_t>(gn), -1);
  for (int e : d.global_element)
    for (int I = 0; I < 8; ++I) local_of[gm.connectivity[8 * e + I]] = 0;
  for (int n = 0; n < gn; ++n)
    if (local_of[n] == 0) {
      local_of[n] = static_cast<int>(d.global_node.size());
      d.global_node.push_back(n);
    }
  const int ln = static_cast<int>(d.global_node.size()), le = static_cast<int>(d.global_element.size());
  d.owned.resize(static_cast<std::size_t>(ln));
  for (int l = 0; l < ln; ++l) {
    d.owned[l] = d.node_owner_[d.global_node[l]] == me ? 1.0 : 0.0;
    if (d.owned[l] > 0.0) {
      ++d.owned_nodes_;
      d.owned_local_nodes_.push_back(l);
    }
  }
  std::vector<int> local_element_of(static_cast<std::size_t>(ge), -1);
  for (int l = 0; l < le; ++l) local_element_of[d.global_element[l]] = l;

  // Halo lists: for every neighbour rank, the shared local nodes in ascending order.
  std::vector<std::vector<int>> with(static_cast<std::size_t>(ranks));
  std::vector<int> shared_slot(static_cast<std::size_t>(ln), -1);
  {
    std::size_t k = 0;
    while (k < holders.size()) {
      std::size_t j = k;
      while (j < holders.size() && holders[j].first == holders[k].first) ++j;
      const int node = holders[k].first, l = local_of[node];
      if (l >= 0 && j - k > 1) {
        shared_slot[l] = static_cast<int>(d.shared_nodes_.size());
        d.shared_nodes_.push_back(l);
        for (std::size_t q = k; q < j; ++q)
          if (holders[q].second != me) with[holders[q].second].push_back(l);
      }
      k = j;
    }
  }
  d.neighbour_offset_.push_back(0);
  for (int r = 0; r < ranks; ++r) {
    if (with[r].empty()) continue;
    d.neighbours_.push_back(r);
    for (int l : with[r]) {
      d.neighbour_nodes_.push_back(l);
      d.neighbour_slot_.push_back(shared_slot[l]);
    }
    d.neighbour_offset_.push_back(static_cast<int>(d.neighbour_nodes_.size()));
  }
  d.send_.assign(3 * d.neighbour_nodes_.size(), 0.0);
  d.recv_.assign(3 * d.neighbour_nodes_.size(), 0.0);
  d.sum_.assign(3 * d.shared_nodes_.size(), 0.0);
  d.requests_.assign(2 * d.neighbours_.size(), MPI_REQUEST_NULL);

  // Mesh.
  mesh::Mesh& m = local.mesh;
  m.coordinates.resize(3 * static_cast<std::size_t>(ln));
  for (int l = 0; l < ln; ++l)
    for (int i = 0; i < 3; ++i) m.coordinates[3 * l + i] = gm.coordinates[3 * d.global_node[l] + i];
  m.connectivity.resize(8 * static_cast<std::size_t>(le));
  for (int l = 0; l < le; ++l)
    for (int I = 0; I < 8; ++I) m.connectivity[8 * l + I] = local_of[gm.connectivity[8 * d.global_element[l] + I]];
  for (const auto& [name, nodes] : gm.node_sets) {
    auto& out = m.node_sets[name];
    for (int n : nodes)
      if (local_of[n] >= 0) out.push_back(local_of[n]);
  }
  for (const auto& [name, sides] : gm.side_sets) {
    auto& out = m.side_sets[name];
    for (const auto& s : sides)
      if (local_element_of[s.element] >= 0) out.push_back({local_element_of[s.element], s.face});
  }

  // Element blocks: the owned elements of each block, in order (blocks are contiguous ranges).
  for (std::size_t b = 0; b < global.blocks.size(); ++b) {
    const ElementBlock& g = global.blocks[b];
    ElementBlock blk;
    blk.name = g.name;
    blk.material = g.material;
    blk.formulation = g.formulation;
    blk.linear_bulk_viscosity = g.linear_bulk_viscosity;
    blk.quadratic_bulk_viscosity = g.quadratic_bulk_viscosity;
    blk.hourglass_stiffness = g.hourglass_stiffness;
    blk.hourglass_viscosity = g.hourglass_viscosity;
    blk.rho_c = g.rho_c;
    std::vector<int> members;
    for (int e = 0; e < g.count; ++e)
      if (part[g.first_element + e] == me) members.push_back(e);
    blk.count = static_cast<int>(members.size());
    blk.first_element = members.empty() ? 0 : local_element_of[g.first_element + members[0]];
    auto take = [&](const std::vector<double>& from, std::vector<double>& to) {
      if (from.empty() || g.count == 0) return;
      const std::size_t stride = from.size() / static_cast<std::size_t>(g.count);
      to.reserve(stride * members.size());
      for (int e : members) to.insert(to.end(), from.begin() + stride * e, from.begin() + stride * (e + 1));
    };
    blk.B0 = select_interleaved(g.B0, members, 24);
    take(g.volume0, blk.volume0);
    take(g.length0, blk.length0);
    take(g.mass_scale, blk.mass_scale);
    blk.hg_coefficients = select_interleaved(g.hg_coefficients, members, 12);
    take(g.hg_k, blk.hg_k);
    take(g.hg_c, blk.hg_c);
    blk.inv_jacobian = select_interleaved(g.inv_jacobian, members, 72);
    blk.wdetJ = select_interleaved(g.wdetJ, members, 8);
    take(g.stress, blk.stress);
    if (g.formulation == inputs::ElementFormulation::mean_quadrature)
      take(g.state, blk.state);
    else
      blk.state = select_interleaved(g.state, members, 8 * materials::state_size_of(g.material));
    m.blocks.push_back({blk.name, blk.first_element, blk.count});
    local.blocks.push_back(std::move(blk));
  }
  local.element_block.resize(static_cast<std::size_t>(le));
  for (int l = 0; l < le; ++l) local.element_block[l] = global.element_block[d.global_element[l]];

  // Nodal data: the global lumped mass (already summed over all elements), initial velocities.
  local.mass.resize(static_cast<std::size_t>(ln));
  local.initial_velocity.resize(3 * static_cast<std::size_t>(ln));
  for (int l = 0; l < ln; ++l) {
    local.mass[l] = global.mass[d.global_node[l]];
    for (int i = 0; i < 3; ++i) local.initial_velocity[3 * l + i] = global.initial_velocity[3 * d.global_node[l] + i];
  }
  // Constraints on every local copy of a node (each copy computes the same velocity).
  const auto& gc = global.constraints;
  for (std::size_t k = 0; k < gc.dof.size(); ++k) {
    const int l = local_of[gc.dof[k] / 3];
    if (l < 0) continue;
    local.constraints.dof.push_back(3 * l + gc.dof[k] % 3);
    local.constraints.kind.push_back(gc.kind[k]);
    local.constraints.function.push_back(gc.function[k]);
    local.constraints.scale.push_back(gc.scale[k]);
  }
  // Pressure faces go with their element: each face's force is added once, then summed.
  for (const auto& p : global.pressures) {
    PressureLoad q;
    q.function = p.function;
    q.scale = p.scale;
    for (std::size_t f = 0; f < p.face_element.size(); ++f) {
      if (part[p.face_element[f]] != me) continue;
      q.face_element.push_back(local_element_of[p.face_element[f]]);
      for (int a = 0; a < 4; ++a) q.face_nodes.push_back(local_of[p.face_nodes[4 * f + a]]);
    }
    local.pressures.push_back(std::move(q));
  }
  // Prescribed nodal forces on the owner's copy only: the partial forces of shared nodes are summed
  // over the ranks, so every copy loading the node would multiply the force.
  for (const auto& p : global.nodal_forces) {
    NodalForceLoad q;
    q.function = p.function;
    q.scale = p.scale;
    for (int dof : p.dof)
      if (const int l = local_of[dof / 3]; l >= 0 && d.owned[l] > 0.0) q.dof.push_back(3 * l + dof % 3);
    local.nodal_forces.push_back(std::move(q));
  }
  // Dashpots: per-node coefficients already summed over all faces.
  const auto& gs = global.silent;
  for (std::size_t k = 0; k < gs.node.size(); ++k) {
    const int l = local_of[gs.node[k]];
    if (l < 0) continue;
    local.silent.node.push_back(l);
    for (int i = 0; i < 3; ++i) local.silent.normal.push_back(gs.normal[3 * k + i]);
    local.silent.c_normal.push_back(gs.c_normal[k]);
    local.silent.c_tangential.push_back(gs.c_tangential[k]);
  }
  local.functions = std::move(global.functions);
  local.function_names = std::move(global.function_names);
  local.mass_damping = global.mass_damping;
  local.total_mass = global.total_mass;
  local.mass_scaling = global.mass_scaling;
  local.block_body = global.block_body;
  local.contact = std::move(global.contact);
  local.preflight = std::move(global.preflight);
  local.setup = std::move(global.setup);
  return local;
}

}  // namespace tribex::solver::parallel
