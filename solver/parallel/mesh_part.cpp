// SPDX-License-Identifier: MIT
#include "solver/parallel/mesh_part.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "solver/errors.hpp"
#include "solver/parallel/bytes.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver::parallel {
namespace {

void write_mesh(ByteWriter& w, const mesh::Mesh& m) {
  w.values(m.coordinates);
  w.values(m.connectivity);
  w.count(m.blocks.size());
  for (const auto& b : m.blocks) {
    w.text(b.name);
    w.values(std::vector<int>{b.first_element, b.element_count});
  }
  w.count(m.node_sets.size());
  for (const auto& [name, nodes] : m.node_sets) {
    w.text(name);
    w.values(nodes);
  }
  w.count(m.side_sets.size());
  for (const auto& [name, sides] : m.side_sets) {
    w.text(name);
    w.values(sides);
  }
}

mesh::Mesh read_mesh(ByteReader& r) {
  mesh::Mesh m;
  m.coordinates = r.values<double>();
  m.connectivity = r.values<int>();
  for (std::size_t k = r.count(); k > 0; --k) {
    mesh::Block b;
    b.name = r.text();
    const auto range = r.values<int>();
    b.first_element = range.at(0);
    b.element_count = range.at(1);
    m.blocks.push_back(std::move(b));
  }
  for (std::size_t k = r.count(); k > 0; --k) {
    std::string name = r.text();
    m.node_sets[name] = r.values<int>();
  }
  for (std::size_t k = r.count(); k > 0; --k) {
    std::string name = r.text();
    m.side_sets[name] = r.values<mesh::Side>();
  }
  return m;
}

void write_sizes(ByteWriter& w, const std::map<std::string, int>& sizes) {
  w.count(sizes.size());
  for (const auto& [name, n] : sizes) {
    w.text(name);
    w.count(static_cast<std::size_t>(n));
  }
}

std::map<std::string, int> read_sizes(ByteReader& r) {
  std::map<std::string, int> sizes;
  for (std::size_t k = r.count(); k > 0; --k) {
    std::string name = r.text();
    sizes[name] = static_cast<int>(r.count());
  }
  return sizes;
}

constexpr int part_tag = 23;

}  // namespace

std::vector<char> pack_part(const MeshPart& p) {
  ByteWriter w;
  write_mesh(w, p.mesh);
  w.values(p.global_node);
  w.values(p.global_element);
  w.values(p.holder_offset);
  w.values(p.holder_rank);
  w.values(std::vector<int>{p.global_node_count, p.global_element_count});
  write_sizes(w, p.node_set_size);
  write_sizes(w, p.side_set_size);
  return std::move(w.bytes);
}

MeshPart unpack_part(const std::vector<char>& bytes) {
  ByteReader r(bytes);
  MeshPart p;
  p.mesh = read_mesh(r);
  p.global_node = r.values<int>();
  p.global_element = r.values<int>();
  p.holder_offset = r.values<int>();
  p.holder_rank = r.values<int>();
  const auto counts = r.values<int>();
  p.global_node_count = counts.at(0);
  p.global_element_count = counts.at(1);
  p.node_set_size = read_sizes(r);
  p.side_set_size = read_sizes(r);
  return p;
}

NodeHolders node_holders(const mesh::Mesh& mesh, const std::vector<int>& part) {
  const int nn = mesh.node_count();
  // The part of the first element reaching each node; only the nodes a second part reaches (the
  // partition boundary) collect their parts as (node, part) pairs: 5 B per node and 8 B per boundary
  // incidence, not 4 B per element corner (rank 0 runs it on the whole mesh).
  std::vector<int> first(static_cast<std::size_t>(nn), -1);
  std::vector<char> boundary(static_cast<std::size_t>(nn), 0);
  const std::size_t corners = mesh.connectivity.size();
  for (std::size_t k = 0; k < corners; ++k) {
    const int n = mesh.connectivity[k], p = part[k / 8];
    if (first[n] < 0)
      first[n] = p;
    else if (first[n] != p)
      boundary[n] = 1;
  }
  for (int n = 0; n < nn; ++n)
    if (first[n] < 0) throw orphan_node_error(n);
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t k = 0; k < corners; ++k)
    if (const int n = mesh.connectivity[k]; boundary[n]) pairs.emplace_back(n, part[k / 8]);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  NodeHolders h;
  h.offset.assign(static_cast<std::size_t>(nn) + 1, 0);
  h.rank.reserve(static_cast<std::size_t>(nn) + pairs.size());
  std::size_t j = 0;
  for (int n = 0; n < nn; ++n) {
    if (!boundary[n]) {
      h.rank.push_back(first[n]);
    } else {
      for (; j < pairs.size() && pairs[j].first == n; ++j) h.rank.push_back(pairs[j].second);
    }
    h.offset[n + 1] = static_cast<int>(h.rank.size());
  }
  return h;
}

MeshPart split_mesh(const mesh::Mesh& whole, const std::vector<int>& part, const NodeHolders& holders, int rank) {
  MeshPart p;
  const int gn = whole.node_count(), ge = whole.element_count();
  p.global_node_count = gn;
  p.global_element_count = ge;
  for (int e = 0; e < ge; ++e)
    if (part[e] == rank) p.global_element.push_back(e);
  std::vector<int> local_of(static_cast<std::size_t>(gn), -1);
  for (int e : p.global_element)
    for (int I = 0; I < 8; ++I) local_of[whole.connectivity[8 * static_cast<std::size_t>(e) + I]] = 0;
  for (int n = 0; n < gn; ++n)
    if (local_of[n] == 0) {
      local_of[n] = static_cast<int>(p.global_node.size());
      p.global_node.push_back(n);
    }
  const std::size_t ln = p.global_node.size(), le = p.global_element.size();
  mesh::Mesh& m = p.mesh;
  m.coordinates.resize(3 * ln);
  p.holder_offset.assign(ln + 1, 0);
  for (std::size_t l = 0; l < ln; ++l) {
    const int n = p.global_node[l];
    for (int i = 0; i < 3; ++i) m.coordinates[3 * l + i] = whole.coordinates[3 * static_cast<std::size_t>(n) + i];
    p.holder_rank.insert(p.holder_rank.end(), holders.rank.begin() + holders.offset[n],
                         holders.rank.begin() + holders.offset[n + 1]);
    p.holder_offset[l + 1] = static_cast<int>(p.holder_rank.size());
  }
  m.connectivity.resize(8 * le);
  for (std::size_t l = 0; l < le; ++l)
    for (int I = 0; I < 8; ++I)
      m.connectivity[8 * l + I] = local_of[whole.connectivity[8 * static_cast<std::size_t>(p.global_element[l]) + I]];
  // Blocks are contiguous ranges of global elements, so of local ones too.
  for (const auto& b : whole.blocks) {
    const auto first = std::lower_bound(p.global_element.begin(), p.global_element.end(), b.first_element);
    const auto last = std::lower_bound(first, p.global_element.end(), b.first_element + b.element_count);
    m.blocks.push_back({b.name, static_cast<int>(first - p.global_element.begin()), static_cast<int>(last - first)});
  }
  for (const auto& [name, nodes] : whole.node_sets) {
    auto& out = m.node_sets[name];
    for (int n : nodes)
      if (local_of[n] >= 0) out.push_back(local_of[n]);
    p.node_set_size[name] = static_cast<int>(nodes.size());
  }
  for (const auto& [name, sides] : whole.side_sets) {
    auto& out = m.side_sets[name];
    for (const auto& s : sides)
      if (part[s.element] == rank) {
        const auto at = std::lower_bound(p.global_element.begin(), p.global_element.end(), s.element);
        out.push_back({static_cast<int>(at - p.global_element.begin()), s.face});
      }
    p.side_set_size[name] = static_cast<int>(sides.size());
  }
  return p;
}

MeshPart distribute_mesh(const mesh::Mesh* whole, const std::vector<int>* part, const NodeHolders* holders) {
  const int me = rank(), ranks = size();
  constexpr std::size_t piece = std::size_t(1) << 30;
  if (me == 0) {
    for (int r = 1; r < ranks; ++r) {
      const std::vector<char> bytes = pack_part(split_mesh(*whole, *part, *holders, r));
      long long n = static_cast<long long>(bytes.size());
      MPI_Send(&n, 1, MPI_LONG_LONG, r, part_tag, MPI_COMM_WORLD);
      for (std::size_t at = 0; at < bytes.size(); at += piece)
        MPI_Send(bytes.data() + at, static_cast<int>(std::min(piece, bytes.size() - at)), MPI_BYTE, r, part_tag,
                 MPI_COMM_WORLD);
    }
    return split_mesh(*whole, *part, *holders, 0);
  }
  long long n = 0;
  MPI_Recv(&n, 1, MPI_LONG_LONG, 0, part_tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  std::vector<char> bytes(static_cast<std::size_t>(n));
  for (std::size_t at = 0; at < bytes.size(); at += piece)
    MPI_Recv(bytes.data() + at, static_cast<int>(std::min(piece, bytes.size() - at)), MPI_BYTE, 0, part_tag,
             MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return unpack_part(bytes);
}

void broadcast_bytes(std::vector<char>& bytes, int root) {
  if (size() == 1) return;
  long long n = static_cast<long long>(bytes.size());
  MPI_Bcast(&n, 1, MPI_LONG_LONG, root, MPI_COMM_WORLD);
  bytes.resize(static_cast<std::size_t>(n));
  constexpr std::size_t piece = std::size_t(1) << 30;
  for (std::size_t at = 0; at < bytes.size(); at += piece)
    MPI_Bcast(bytes.data() + at, static_cast<int>(std::min(piece, bytes.size() - at)), MPI_BYTE, root, MPI_COMM_WORLD);
}

}  // namespace tribex::solver::parallel
