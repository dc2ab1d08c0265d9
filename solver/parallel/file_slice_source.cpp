// SPDX-License-Identifier: MIT
// file_slice_source.hpp: an Exodus file in slices, routed between the ranks.
#include "solver/parallel/file_slice_source.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <limits>
#include <set>
#include <tuple>
#include <utility>

#include "solver/parallel/sparse_exchange.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/element_slab.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::solver::parallel {
namespace {

// The even split of a set's `entries` over the ranks: this rank's [first, first + count).
std::pair<long long, long long> my_share(long long entries) {
  const long long ranks = size(), me = rank();
  const long long first = entries * me / ranks;
  return {first, entries * (me + 1) / ranks - first};
}

// Records of `width` ints in `data`, each to the rank `to(record)`: the records regrouped by destination
// (stable: a rank's records keep their order) and exchanged; returns what this rank received.
template <class To>
std::vector<int> send_records(const std::vector<int>& data, int width, To to) {
  const int ranks = size();
  const std::size_t records = data.size() / static_cast<std::size_t>(width);
  std::vector<int> count(static_cast<std::size_t>(ranks), 0), dest(records);
  for (std::size_t k = 0; k < records; ++k) count[static_cast<std::size_t>(dest[k] = to(&data[k * width]))] += width;
  std::vector<int> at(static_cast<std::size_t>(ranks) + 1, 0);
  for (int r = 0; r < ranks; ++r) at[r + 1] = at[r] + count[r];
  std::vector<int> out(data.size());
  for (std::size_t k = 0; k < records; ++k) {
    std::copy_n(&data[k * width], width, &out[static_cast<std::size_t>(at[dest[k]])]);
    at[dest[k]] += width;
  }
  std::vector<int> received;
  return exchange(count, out, received);
}

// True if the quad's 4 nodes are `face` up to a cyclic rotation (the same outward normal: read_gmsh's test).
bool same_rotation(const int* quad, const std::array<int, 4>& face) {
  for (int r = 0; r < 4; ++r) {
    bool equal = true;
    for (int k = 0; k < 4 && equal; ++k) equal = quad[k] == face[static_cast<std::size_t>((k + r) % 4)];
    if (equal) return true;
  }
  return false;
}

// Every rank's `mine`, in rank order, on every rank.
std::vector<int> gather_all(const std::vector<int>& mine) {
  const int ranks = size(), n = static_cast<int>(mine.size());
  std::vector<int> count(static_cast<std::size_t>(ranks)), at(static_cast<std::size_t>(ranks) + 1, 0);
  MPI_Allgather(&n, 1, MPI_INT, count.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 0; r < ranks; ++r) at[r + 1] = at[r] + count[r];
  std::vector<int> all(static_cast<std::size_t>(at[ranks]));
  MPI_Allgatherv(mine.data(), n, MPI_INT, all.data(), count.data(), at.data(), MPI_INT, MPI_COMM_WORLD);
  return all;
}

}  // namespace

FileSliceSource::FileSliceSource(const std::string& path, bool walk_header)
    : FileSliceSource(std::make_unique<mesh::ExodusSlices>(path, walk_header)) {}

FileSliceSource::FileSliceSource(std::unique_ptr<mesh::MeshSlices> file) : file_(std::move(file)) {
  node_count_ = file_->node_count();
  const int ranks = size(), me = rank();
  element_offset_ = slab_offsets(file_->element_count(), ranks);
  node_offset_ = slab_offsets(file_->node_count(), ranks);
  slab_ = file_->connectivity(element_offset_[me], element_offset_[me + 1] - element_offset_[me]);
  xyz_ = file_->coordinates(node_offset_[me], node_offset_[me + 1] - node_offset_[me]);
  read_set_slices();
  file_->close();  // all this rank reads of it: the library's buffers are not held through the partition
}

void FileSliceSource::read_set_slices() {
  const auto& ss = file_->side_sets();
  for (std::size_t s = 0; s < ss.names.size(); ++s) {
    const auto [first, count] = my_share(ss.entries[s]);
    if (file_->sides_are_quads()) {  // matched to hex faces in route()
      const std::vector<int> q = file_->quads(s, first, count);
      for (std::size_t k = 0; k < q.size(); k += 5)
        my_quads_.insert(my_quads_.end(), {q[k], static_cast<int>(s), q[k + 1], q[k + 2], q[k + 3], q[k + 4]});
      continue;
    }
    const std::vector<mesh::Side> sides = file_->side_set(s, first, count);
    for (std::size_t k = 0; k < sides.size(); ++k)
      my_sides_.push_back({sides[k].element, static_cast<int>(s), static_cast<int>(first + static_cast<long long>(k)),
                           sides[k].face});
  }
  const auto& ns = file_->node_sets();
  node_set_names_ = ns.names;
  for (std::size_t s = 0; s < ns.names.size(); ++s) {
    const auto [first, count] = my_share(ns.entries[s]);
    for (int n : file_->node_set(s, first, count)) {
      my_set_nodes_.push_back(n);
      my_set_nodes_.push_back(static_cast<int>(s));
    }
  }
  // read_exodus: a side set's nodes are also a node set of its name unless the file has one.
  for (const auto& name : ss.names)
    if (std::find(ns.names.begin(), ns.names.end(), name) == ns.names.end()) node_set_names_.push_back(name);
}

// A gmsh file's side sets are quads: read_gmsh (mesh/gmsh_io.cpp) matches each to the hex face with its
// nodes whose outward order (hex8_face_nodes) is the quad's up to a rotation; an interior face belongs to two
// hexes, one per orientation. Every rank gets every quad (the side sets' size, the mesh's surface, not its
// volume) and offers its slab's faces; the smallest matching (element, face) wins, one of the orientation if
// any (read_gmsh's pick among two faces of neither orientation is its sort's; a mesh has none). A side's
// position in its set is element * 6 + face: read_gmsh sorts each side set by (element, face).
void FileSliceSource::match_quads() {
  const std::vector<int> quads = gather_all(my_quads_);  // [quad][6]: tag, set, 4 nodes
  my_quads_ = {};
  const std::size_t n = quads.size() / 6;
  std::vector<std::pair<std::array<int, 4>, std::size_t>> keys(n);
  for (std::size_t q = 0; q < n; ++q) {
    std::copy_n(&quads[6 * q + 2], 4, keys[q].first.begin());
    std::sort(keys[q].first.begin(), keys[q].first.end());
    keys[q].second = q;
  }
  std::sort(keys.begin(), keys.end());
  constexpr long long none = std::numeric_limits<long long>::max();
  std::vector<long long> best(2 * n, none);  // [quad] of its orientation; [n + quad] of either
  const int first = element_offset_[rank()];
  for (std::size_t e = 0; e < slab_.size() / 8; ++e)
    for (int f = 0; f < 6; ++f) {
      std::array<int, 4> face{}, key{};
      for (int k = 0; k < 4; ++k) face[k] = slab_[8 * e + static_cast<std::size_t>(mesh::hex8_face_nodes[f][k])];
      key = face;
      std::sort(key.begin(), key.end());
      const long long side = 6 * (first + static_cast<long long>(e)) + f;
      auto it = std::lower_bound(keys.begin(), keys.end(), std::pair(key, std::size_t{0}));
      for (; it != keys.end() && it->first == key; ++it) {
        const std::size_t q = it->second;
        best[n + q] = std::min(best[n + q], side);
        if (same_rotation(&quads[6 * q + 2], face)) best[q] = std::min(best[q], side);
      }
    }
  MPI_Allreduce(MPI_IN_PLACE, best.data(), static_cast<int>(best.size()), MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
  const auto& ss = file_->side_sets();
  for (std::size_t q = 0; q < n; ++q) {
    const long long side = best[q] != none ? best[q] : best[n + q];
    const std::string& set = ss.names[static_cast<std::size_t>(quads[6 * q + 1])];
    if (side == none)  // read_gmsh's words: every rank alike
      throw mesh::MeshError(file_->path() + ": quad element tag " + std::to_string(quads[6 * q]) + " of physical surface '" +
                            set + "' is not a face of any hex; side sets must be faces of the volume mesh");
    const int element = static_cast<int>(side / 6);
    if (home_of(element_offset_, element) == rank())
      my_sides_.push_back({element, quads[6 * q + 1], static_cast<int>(side), static_cast<int>(side % 6)});
  }
}

void FileSliceSource::route() {
  if (file_->sides_are_quads()) match_quads();
  route_sides();
  route_node_sets();
}

void FileSliceSource::route_sides() {
  std::vector<int> data;
  data.reserve(4 * my_sides_.size());
  for (const SideEntry& e : my_sides_) data.insert(data.end(), {e.element, e.set, e.position, e.face});
  my_sides_ = {};
  const std::vector<int> got = send_records(data, 4, [&](const int* r) { return home_of(element_offset_, r[0]); });
  sides_.clear();
  for (std::size_t k = 0; k + 3 < got.size(); k += 4) sides_.push_back({got[k], got[k + 1], got[k + 2], got[k + 3]});
  std::sort(sides_.begin(), sides_.end(), [](const SideEntry& a, const SideEntry& b) {
    return std::tie(a.element, a.set, a.position) < std::tie(b.element, b.set, b.position);
  });
}

void FileSliceSource::route_node_sets() {
  // (node, set) pairs to the nodes' homes: the node sets' slices, the sides' nodes of the side sets made node
  // sets, and (node, -1) for every node of the slab (the nodes some element uses).
  std::vector<int> data = std::move(my_set_nodes_);
  my_set_nodes_ = {};
  const auto& ss = file_->side_sets();
  const int first = element_offset_[rank()];
  for (const SideEntry& e : sides_) {
    const auto it = std::find(node_set_names_.begin(), node_set_names_.end(), ss.names[static_cast<std::size_t>(e.set)]);
    const int set = static_cast<int>(it - node_set_names_.begin());
    if (set < static_cast<int>(file_->node_sets().names.size())) continue;  // the file has a node set of its name
    for (int a : mesh::hex8_face_nodes[e.face])
      data.insert(data.end(), {slab_[8 * static_cast<std::size_t>(e.element - first) + a], set});
  }
  std::vector<int> used(slab_);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  for (int n : used) data.insert(data.end(), {n, -1});
  used = {};
  const std::vector<int> got = send_records(data, 2, [&](const int* r) { return home_of(node_offset_, r[0]); });
  data = {};
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(got.size() / 2);
  for (std::size_t k = 0; k + 1 < got.size(); k += 2) pairs.emplace_back(got[k], got[k + 1]);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  // The sets holding each home node (CSR); a home node with no (node, -1) pair is in no element.
  const int lo = node_offset_[rank()], hi = node_offset_[rank() + 1];
  member_offset_.assign(static_cast<std::size_t>(hi - lo) + 1, 0);
  member_set_.clear();
  // [set] its home nodes; then the unused nodes; then the unused nodes' set memberships (read_gmsh refuses those)
  std::vector<long long> sizes(node_set_names_.size() + 2, 0);
  std::vector<char> in_element(static_cast<std::size_t>(hi - lo), 0);
  std::size_t k = 0;
  for (int n = lo; n < hi; ++n) {
    const std::size_t start = member_set_.size();
    char& mine = in_element[static_cast<std::size_t>(n - lo)];
    for (; k < pairs.size() && pairs[k].first == n; ++k) {
      if (pairs[k].second < 0) mine = 1;
      else member_set_.push_back(pairs[k].second);
    }
    if (!mine) sizes.back() += static_cast<long long>(member_set_.size() - start);
    if (!mine) member_set_.resize(start);  // read_exodus drops a node no element uses from its sets
    for (std::size_t j = start; j < member_set_.size(); ++j) ++sizes[static_cast<std::size_t>(member_set_[j])];
    sizes[node_set_names_.size()] += !mine;
    member_offset_[static_cast<std::size_t>(n - lo) + 1] = static_cast<int>(member_set_.size());
  }
  MPI_Allreduce(MPI_IN_PLACE, sizes.data(), static_cast<int>(sizes.size()), MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  for (std::size_t s = 0; s < node_set_names_.size(); ++s) node_set_size_[node_set_names_[s]] = static_cast<int>(sizes[s]);
  unused_ = sizes[node_set_names_.size()];
  if (file_->sides_are_quads() && sizes.back() > 0)  // every rank alike
    throw mesh::MeshError(file_->path() + ": a physical point or curve group has a node that belongs to no hex; sets "
                          "must lie on the volume mesh");
  if (unused_ > 0) renumber(in_element);
}

// read_exodus drops the nodes no element uses and numbers the others in file order; so does this. A home's
// used nodes are one run of the new numbering, so each home keeps its nodes (coordinates and sets compacted)
// under a new, uneven range, and the slab ranks ask the old homes for their nodes' new numbers.
void FileSliceSource::renumber(const std::vector<char>& used) {
  const int ranks = size(), me = rank(), lo = node_offset_[me];
  int kept = 0;
  for (char u : used) kept += u;
  std::vector<int> counts(static_cast<std::size_t>(ranks)), new_offset(static_cast<std::size_t>(ranks) + 1, 0);
  MPI_Allgather(&kept, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 0; r < ranks; ++r) new_offset[r + 1] = new_offset[r] + counts[r];
  std::vector<int> new_of(used.size(), -1), offset(1, 0), sets;
  std::vector<double> xyz;
  for (std::size_t n = 0, next = static_cast<std::size_t>(new_offset[me]); n < used.size(); ++n) {
    if (!used[n]) continue;
    new_of[n] = static_cast<int>(next++);
    xyz.insert(xyz.end(), xyz_.begin() + 3 * static_cast<std::ptrdiff_t>(n), xyz_.begin() + 3 * static_cast<std::ptrdiff_t>(n + 1));
    sets.insert(sets.end(), member_set_.begin() + member_offset_[n], member_set_.begin() + member_offset_[n + 1]);
    offset.push_back(static_cast<int>(sets.size()));
  }
  xyz_ = std::move(xyz);
  member_set_ = std::move(sets);
  member_offset_ = std::move(offset);
  // The slab's nodes (all used) to their old homes, and their new numbers back in the same order.
  std::vector<int> nodes(slab_);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::vector<int> count(static_cast<std::size_t>(ranks), 0), from, got;
  for (int n : nodes) ++count[static_cast<std::size_t>(home_of(node_offset_, n))];
  std::vector<int> answer = exchange(count, nodes, from);
  for (int& n : answer) n = new_of[static_cast<std::size_t>(n - lo)];
  answer = exchange(from, answer, got);
  for (int& n : slab_)
    n = answer[static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), n) - nodes.begin())];
  node_offset_ = std::move(new_offset);
  node_count_ = node_offset_[static_cast<std::size_t>(ranks)];
}

std::map<std::string, int> FileSliceSource::side_set_sizes() const {
  std::map<std::string, int> sizes;
  const auto& ss = file_->side_sets();
  for (std::size_t s = 0; s < ss.names.size(); ++s) sizes[ss.names[s]] = static_cast<int>(ss.entries[s]);
  return sizes;
}

// Asks the slab ranks for `elements` (ascending): `conn` gets their 8 global nodes each, `sides` their
// side-set entries (the element's index in `elements`).
void FileSliceSource::ask_elements(const std::vector<int>& elements, std::vector<int>& conn,
                                            std::vector<SideEntry>& sides) const {
  const int ranks = size(), first = element_offset_[rank()];
  std::vector<int> count(static_cast<std::size_t>(ranks), 0);
  for (int e : elements) ++count[static_cast<std::size_t>(home_of(element_offset_, e))];
  std::vector<int> from;
  const std::vector<int> asked = exchange(count, elements, from);  // ascending elements, grouped by asker
  // The reply per element: its 8 nodes, its number of side entries, then (set, position, face) of each.
  std::vector<int> reply, reply_count(static_cast<std::size_t>(ranks), 0);
  std::size_t k = 0;
  for (int r = 0; r < ranks; ++r)
    for (int i = 0; i < from[r]; ++i, ++k) {
      const std::size_t before = reply.size();
      const int e = asked[k];
      reply.insert(reply.end(), slab_.begin() + 8 * (e - first), slab_.begin() + 8 * (e - first + 1));
      const auto range = std::equal_range(sides_.begin(), sides_.end(), SideEntry{e, 0, 0, 0},
                                          [](const SideEntry& a, const SideEntry& b) { return a.element < b.element; });
      reply.push_back(static_cast<int>(range.second - range.first));
      for (auto it = range.first; it != range.second; ++it) reply.insert(reply.end(), {it->set, it->position, it->face});
      reply_count[r] += static_cast<int>(reply.size() - before);
    }
  std::vector<int> got;
  const std::vector<int> answer = exchange(reply_count, reply, got);
  // Answers come in home order, each home's in the order asked: the elements ascending.
  conn.assign(8 * elements.size(), 0);
  std::size_t at = 0;
  for (std::size_t l = 0; l < elements.size(); ++l) {
    std::copy_n(answer.begin() + static_cast<std::ptrdiff_t>(at), 8, conn.begin() + static_cast<std::ptrdiff_t>(8 * l));
    at += 8;
    const int n = answer[at++];
    for (int j = 0; j < n; ++j, at += 3) sides.push_back({static_cast<int>(l), answer[at], answer[at + 1], answer[at + 2]});
  }
}

// Asks the homes of `global_node` (ascending) for their coordinates and node sets, into m.
void FileSliceSource::ask_nodes(const std::vector<int>& global_node, mesh::Mesh& m) const {
  const int ranks = size(), lo = node_offset_[rank()];
  std::vector<int> count(static_cast<std::size_t>(ranks), 0);
  for (int n : global_node) ++count[static_cast<std::size_t>(home_of(node_offset_, n))];
  std::vector<int> from;
  const std::vector<int> asked = exchange(count, global_node, from);
  std::vector<double> xyz;
  std::vector<int> sets, xyz_count(static_cast<std::size_t>(ranks), 0), set_count(static_cast<std::size_t>(ranks), 0);
  xyz.reserve(3 * asked.size());
  std::size_t k = 0;
  for (int r = 0; r < ranks; ++r)
    for (int i = 0; i < from[r]; ++i, ++k) {
      const std::size_t n = static_cast<std::size_t>(asked[k] - lo);
      xyz.insert(xyz.end(), xyz_.begin() + 3 * static_cast<std::ptrdiff_t>(n), xyz_.begin() + 3 * static_cast<std::ptrdiff_t>(n + 1));
      sets.push_back(member_offset_[n + 1] - member_offset_[n]);
      sets.insert(sets.end(), member_set_.begin() + member_offset_[n], member_set_.begin() + member_offset_[n + 1]);
      xyz_count[r] += 3;
      set_count[r] += 1 + member_offset_[n + 1] - member_offset_[n];
    }
  std::vector<int> got;
  m.coordinates = exchange(xyz_count, xyz, got);
  const std::vector<int> member = exchange(set_count, sets, got);
  for (const auto& name : node_set_names_) m.node_sets[name];
  std::size_t at = 0;
  for (std::size_t l = 0; l < global_node.size(); ++l) {
    const int n = member[at++];
    for (int j = 0; j < n; ++j) m.node_sets[node_set_names_[static_cast<std::size_t>(member[at++])]].push_back(static_cast<int>(l));
  }
}

mesh::Mesh FileSliceSource::elements_mesh(const std::vector<int>& elements, std::vector<int>& global_node) const {
  mesh::Mesh m;
  std::vector<SideEntry> sides;
  ask_elements(elements, m.connectivity, sides);
  global_node = m.connectivity;
  std::sort(global_node.begin(), global_node.end());
  global_node.erase(std::unique(global_node.begin(), global_node.end()), global_node.end());
  for (int& n : m.connectivity)
    n = static_cast<int>(std::lower_bound(global_node.begin(), global_node.end(), n) - global_node.begin());
  ask_nodes(global_node, m);
  // Blocks are contiguous ranges of global elements, so of local ones too (split_mesh).
  for (const auto& b : file_->blocks()) {
    const auto lo = std::lower_bound(elements.begin(), elements.end(), b.first_element);
    const auto hi = std::lower_bound(lo, elements.end(), b.first_element + b.element_count);
    m.blocks.push_back({b.name, static_cast<int>(lo - elements.begin()), static_cast<int>(hi - lo)});
  }
  // Side sets in each set's order (by position), every set by name.
  std::sort(sides.begin(), sides.end(),
            [](const SideEntry& a, const SideEntry& b) { return std::tie(a.set, a.position) < std::tie(b.set, b.position); });
  const auto& ss = file_->side_sets();
  for (const auto& name : ss.names) m.side_sets[name];
  for (const SideEntry& e : sides) m.side_sets[ss.names[static_cast<std::size_t>(e.set)]].push_back({e.element, e.face});
  return m;
}

std::vector<int> FileSliceSource::side_set_elements(const std::vector<std::string>& names) const {
  const auto& ss = file_->side_sets();
  std::set<int> wanted;
  for (const auto& name : names)
    if (const auto it = std::find(ss.names.begin(), ss.names.end(), name); it != ss.names.end())
      wanted.insert(static_cast<int>(it - ss.names.begin()));
  std::vector<int> mine;
  for (const SideEntry& e : sides_)
    if (wanted.count(e.set) && (mine.empty() || mine.back() != e.element)) mine.push_back(e.element);
  // Every rank's (ascending, disjoint slabs in rank order): gathered in rank order is ascending.
  return gather_all(mine);
}

}  // namespace tribex::solver::parallel
