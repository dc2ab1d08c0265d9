// SPDX-License-Identifier: MIT
#include "solver/parallel/face_dual_graph.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>

#include "mesh/mesh.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver::parallel {
namespace {

constexpr int kFaceRecord = 5;  // the sorted 4 node numbers, then the element
constexpr int kEdgeRecord = 2;  // element, neighbour

// Records of `width` ints bound for each rank, flat per destination.
using Outbox = std::vector<std::vector<int>>;

// Sends every rank its records (MPI_Alltoall of the counts, MPI_Alltoallv of the ints) and returns the
// records received, in source-rank order. One rank: its own records.
std::vector<int> exchange(const Outbox& out) {
  const int ranks = size();
  if (ranks == 1) return out[0];
  std::vector<int> send_count(ranks), recv_count(ranks), send_at(ranks + 1, 0), recv_at(ranks + 1, 0);
  for (int r = 0; r < ranks; ++r) {
    if (out[r].size() > static_cast<std::size_t>(INT32_MAX - send_at[r]))
      throw std::runtime_error("face_dual_graph: more than 2^31 ints to send from one rank");
    send_count[r] = static_cast<int>(out[r].size());
    send_at[r + 1] = send_at[r] + send_count[r];
  }
  MPI_Alltoall(send_count.data(), 1, MPI_INT, recv_count.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int r = 0; r < ranks; ++r) recv_at[r + 1] = recv_at[r] + recv_count[r];
  std::vector<int> send(static_cast<std::size_t>(send_at[ranks])), recv(static_cast<std::size_t>(recv_at[ranks]));
  for (int r = 0; r < ranks; ++r) std::copy(out[r].begin(), out[r].end(), send.begin() + send_at[r]);
  MPI_Alltoallv(send.data(), send_count.data(), send_at.data(), MPI_INT, recv.data(), recv_count.data(), recv_at.data(),
                MPI_INT, MPI_COMM_WORLD);
  return recv;
}

// The rank that matches a face: a 64-bit mix of its sorted node numbers (splitmix64's finaliser, so
// that neighbouring faces spread over the ranks), modulo the rank count. The same on every machine.
int face_rank(const std::array<int, 4>& key, int ranks) {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (int n : key) {
    h ^= static_cast<std::uint64_t>(static_cast<std::uint32_t>(n)) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebULL;
    h ^= h >> 31;
  }
  return static_cast<int>(h % static_cast<std::uint64_t>(ranks));
}

// Every face of the slab as (sorted nodes, global element), sent to its matching rank.
Outbox face_records(const ElementSlab& slab, int ranks) {
  Outbox out(static_cast<std::size_t>(ranks));
  for (int e = 0; e < slab.count; ++e)
    for (const auto& face : mesh::hex8_face_nodes) {
      std::array<int, 4> key;
      for (int k = 0; k < 4; ++k) key[k] = slab.nodes[8 * static_cast<std::size_t>(e) + face[k]];
      std::sort(key.begin(), key.end());
      std::vector<int>& to = out[face_rank(key, ranks)];
      to.insert(to.end(), key.begin(), key.end());
      to.push_back(slab.first + e);
    }
  return out;
}

// The rank whose slab holds global element `e`.
int slab_rank(const std::vector<int>& vertex_offset, int e) {
  return static_cast<int>(std::upper_bound(vertex_offset.begin(), vertex_offset.end(), e) - vertex_offset.begin()) - 1;
}

// Matches the faces received (records of kFaceRecord ints): the elements of one key are neighbours,
// each pair sent both ways to the ranks holding them.
Outbox matched_pairs(const std::vector<int>& faces, const std::vector<int>& vertex_offset, int ranks) {
  // Sorted as whole records (key, then element): contiguous 20-byte moves, no indirection.
  std::vector<std::array<int, kFaceRecord>> record(faces.size() / kFaceRecord);
  for (std::size_t i = 0; i < record.size(); ++i)
    std::copy_n(faces.begin() + static_cast<std::ptrdiff_t>(kFaceRecord * i), kFaceRecord, record[i].begin());
  std::sort(record.begin(), record.end());
  Outbox out(static_cast<std::size_t>(ranks));
  auto send = [&](int a, int b) {
    std::vector<int>& to = out[slab_rank(vertex_offset, a)];
    to.push_back(a);
    to.push_back(b);
  };
  const std::size_t n = record.size();
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i + 1;
    while (j < n && std::equal(record[i].begin(), record[i].begin() + 4, record[j].begin())) ++j;
    for (std::size_t p = i; p < j; ++p)
      for (std::size_t q = p + 1; q < j; ++q) {
        const int a = record[p][4], b = record[q][4];
        if (a == b) continue;  // a face met twice in one (degenerate) element
        send(a, b);
        send(b, a);
      }
    i = j;
  }
  return out;
}

// The slabs' first elements, [rank + 1], from every rank's (first, count).
std::vector<int> gather_offsets(const ElementSlab& slab) {
  const int ranks = size();
  std::vector<int> firsts(static_cast<std::size_t>(2 * ranks));
  const int mine[2] = {slab.first, slab.count};
  if (ranks == 1)
    std::copy(mine, mine + 2, firsts.begin());
  else
    MPI_Allgather(mine, 2, MPI_INT, firsts.data(), 2, MPI_INT, MPI_COMM_WORLD);
  std::vector<int> offset(static_cast<std::size_t>(ranks + 1));
  for (int r = 0; r < ranks; ++r) {
    offset[r] = firsts[2 * r];
    if (r > 0 && offset[r] != offset[r - 1] + firsts[2 * r - 1])
      throw std::runtime_error("face_dual_graph: the ranks' slabs are not contiguous in rank order");
  }
  offset[ranks] = firsts[2 * ranks - 2] + firsts[2 * ranks - 1];
  return offset;
}

}  // namespace

DualGraphRows face_dual_graph(const ElementSlab& slab) {
  const int ranks = size();
  DualGraphRows g;
  g.vertex_offset = gather_offsets(slab);
  const std::vector<int> faces = exchange(face_records(slab, ranks));
  std::vector<int> pairs = exchange(matched_pairs(faces, g.vertex_offset, ranks));
  // CSR of the pairs received, each row sorted and without repeats (two elements sharing two faces).
  const std::size_t n = pairs.size() / kEdgeRecord;
  std::vector<std::array<int, 2>> edge(n);
  for (std::size_t i = 0; i < n; ++i) edge[i] = {pairs[kEdgeRecord * i] - slab.first, pairs[kEdgeRecord * i + 1]};
  pairs = {};
  std::sort(edge.begin(), edge.end());
  edge.erase(std::unique(edge.begin(), edge.end()), edge.end());
  g.offset.assign(static_cast<std::size_t>(slab.count) + 1, 0);
  g.neighbour.reserve(edge.size());
  for (const auto& [e, other] : edge) {
    ++g.offset[static_cast<std::size_t>(e) + 1];
    g.neighbour.push_back(other);
  }
  for (int e = 0; e < slab.count; ++e) g.offset[e + 1] += g.offset[e];
  return g;
}

}  // namespace tribex::solver::parallel
