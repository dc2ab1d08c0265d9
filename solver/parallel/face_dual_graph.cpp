// SPDX-License-Identifier: MIT
#include "solver/parallel/face_dual_graph.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <tuple>

#include "mesh/mesh.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/parallel/sparse_exchange.hpp"

namespace tribex::solver::parallel {
namespace {

using FaceRecord = std::array<int, 5>;  // the sorted 4 node numbers, then the global element
using EdgeRecord = std::array<int, 2>;  // global element, neighbour

// Records bound for the ranks, in one buffer ordered by destination (count[r] of them to rank r).
template <class Record>
struct Outgoing {
  std::vector<int> count;
  std::vector<Record> record;
};

// Packs the records `each(emit)` emits (emit(rank, record)) straight into one send buffer: `each` runs
// twice, once to count each destination's records and once to place them, so that no per-rank lists
// and no second copy are held (the face records are 120 B per element; doubled buffers measured 365 B
// per element of rank 0's peak at 4 ranks on the 1 M-element indenter).
template <class Record, class Each>
Outgoing<Record> pack(int ranks, const Each& each) {
  Outgoing<Record> out;
  out.count.assign(static_cast<std::size_t>(ranks), 0);
  each([&](int rank, const Record&) { ++out.count[rank]; });
  std::vector<std::size_t> at(static_cast<std::size_t>(ranks) + 1, 0);
  for (int r = 0; r < ranks; ++r) at[r + 1] = at[r] + static_cast<std::size_t>(out.count[r]);
  out.record.resize(at[ranks]);
  each([&](int rank, const Record& record) { out.record[at[rank]++] = record; });
  return out;
}

// Sends every rank its records (sparse_counts, then sparse_alltoallv of the ints: sparse_exchange.hpp), freeing the send
// buffer, and returns the records received in source-rank order. One rank: its own records.
template <class Record>
std::vector<Record> exchange(Outgoing<Record>&& out) {
  const int ranks = size();
  if (ranks == 1) return std::move(out.record);
  constexpr int width = static_cast<int>(std::tuple_size_v<Record>);
  const std::vector<int> recv_records = sparse_counts(out.count);
  // MPI's counts and displacements are ints: up to 2^31 ints each way per rank, agreed on by all the
  // ranks so that all of them throw.
  long long sent = 0, received = 0;
  for (int r = 0; r < ranks; ++r) {
    sent += static_cast<long long>(width) * out.count[r];
    received += static_cast<long long>(width) * recv_records[r];
  }
  long long most = std::max(sent, received);
  MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
  if (most > INT32_MAX) throw std::runtime_error("face_dual_graph: more than 2^31 ints to exchange on one rank");
  std::vector<int> send_count(ranks), recv_count(ranks), send_at(ranks + 1, 0), recv_at(ranks + 1, 0);
  for (int r = 0; r < ranks; ++r) {
    send_count[r] = width * out.count[r];
    recv_count[r] = width * recv_records[r];
    send_at[r + 1] = send_at[r] + send_count[r];
    recv_at[r + 1] = recv_at[r] + recv_count[r];
  }
  std::vector<Record> recv(static_cast<std::size_t>(recv_at[ranks] / width));
  sparse_alltoallv(out.record.data(), send_count.data(), send_at.data(), recv.data(), recv_count.data(),
                   recv_at.data(), MPI_INT);
  out = {};
  return recv;
}

// The rank that matches a face: the home of its smallest node in the even split of the node numbers
// (floor(n P / nodes)). A generated mesh, and a mesher's file as a rule, numbers nodes and elements in
// the same sweep, so a slab's faces go to the slab's own rank and its neighbours in rank order: a few
// peers each instead of all of them (a hash spread every slab over every rank: an all-to-all whose
// shared-memory pages every rank kept, docs/measurements/2026-11-29-sparse-exchange.md). Which rank
// matches a face does not change the graph (face_dual_graph sorts its rows), so the partition is the same.
int face_rank(const FaceRecord& face, int ranks, long long nodes) {
  return static_cast<int>(std::min<long long>(static_cast<long long>(face[0]) * ranks / nodes, ranks - 1));
}

// Every face of the slab as (sorted nodes, global element), bound for its matching rank.
Outgoing<FaceRecord> face_records(const ElementSlab& slab, int ranks, long long nodes) {
  return pack<FaceRecord>(ranks, [&](const auto& emit) {
    for (int e = 0; e < slab.count; ++e)
      for (const auto& face : mesh::hex8_face_nodes) {
        FaceRecord record;
        for (int k = 0; k < 4; ++k) record[k] = slab.nodes[8 * static_cast<std::size_t>(e) + face[k]];
        std::sort(record.begin(), record.begin() + 4);
        record[4] = slab.first + e;
        emit(face_rank(record, ranks, nodes), record);
      }
  });
}

// The rank whose slab holds global element `e`.
int slab_rank(const std::vector<int>& vertex_offset, int e) {
  return static_cast<int>(std::upper_bound(vertex_offset.begin(), vertex_offset.end(), e) - vertex_offset.begin()) - 1;
}

// Matches the faces received: the elements of one key are neighbours, each pair bound both ways for
// the ranks holding them. Sorts `faces` (whole records: key, then element).
Outgoing<EdgeRecord> matched_pairs(std::vector<FaceRecord>& faces, const std::vector<int>& vertex_offset, int ranks) {
  std::sort(faces.begin(), faces.end());
  return pack<EdgeRecord>(ranks, [&](const auto& emit) {
    const std::size_t n = faces.size();
    for (std::size_t i = 0; i < n;) {
      std::size_t j = i + 1;
      while (j < n && std::equal(faces[i].begin(), faces[i].begin() + 4, faces[j].begin())) ++j;
      for (std::size_t p = i; p < j; ++p)
        for (std::size_t q = p + 1; q < j; ++q) {
          const int a = faces[p][4], b = faces[q][4];
          if (a == b) continue;  // a face met twice in one (degenerate) element
          emit(slab_rank(vertex_offset, a), EdgeRecord{a, b});
          emit(slab_rank(vertex_offset, b), EdgeRecord{b, a});
        }
      i = j;
    }
  });
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

// The node numbers' bound: one more than the largest any slab uses (at least 1).
long long node_count(const ElementSlab& slab) {
  long long most = 0;
  for (int n : slab.nodes) most = std::max<long long>(most, n);
  if (size() > 1) MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
  return most + 1;
}

}  // namespace

DualGraphRows face_dual_graph(const ElementSlab& slab) {
  const int ranks = size();
  DualGraphRows g;
  g.vertex_offset = gather_offsets(slab);
  std::vector<EdgeRecord> edge;
  {
    std::vector<FaceRecord> faces = exchange(face_records(slab, ranks, node_count(slab)));
    edge = exchange(matched_pairs(faces, g.vertex_offset, ranks));
  }
  // CSR of the pairs received, each row sorted and without repeats (two elements sharing two faces).
  for (EdgeRecord& e : edge) e[0] -= slab.first;
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
