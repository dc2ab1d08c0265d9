// SPDX-License-Identifier: MIT
#include "solver/parallel/partition.hpp"

#include <metis.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "solver/parallel/element_clusters.hpp"

namespace tribex::solver::parallel {
namespace {

// Above this many elements the partition is computed on clusters of elements (element_clusters.hpp)
// rather than on the element graph, whose METIS workspace would be rank 0's peak memory; the
// clusters are sized for a graph of about kClusterGraph vertices, at least kClustersPerPart per part.
constexpr int kClusterAbove = 262144;
constexpr int kClusterGraph = 65536;
constexpr int kClustersPerPart = 16;

// The graph METIS partitions: CSR, optional vertex and edge weights.
struct Graph {
  idx_t vertices = 0, constraints = 1;
  std::vector<idx_t> xadj, adjncy, vertex_weight, edge_weight;
};

// The element dual graph: neighbours share a face (4 nodes).
Graph element_graph(const mesh::Mesh& mesh) {
  const int ne = mesh.element_count();
  idx_t n_elements = ne, n_nodes = mesh.node_count(), n_common = 4, numbering = 0;
  // The connectivity as it is where idx_t is int (METIS reads it, does not write it), else a copy.
  std::vector<idx_t> eptr(static_cast<std::size_t>(ne) + 1), copy;
  for (int e = 0; e <= ne; ++e) eptr[e] = 8 * e;
  idx_t* eind = nullptr;
  if constexpr (sizeof(idx_t) == sizeof(int)) {
    eind = reinterpret_cast<idx_t*>(const_cast<int*>(mesh.connectivity.data()));
  } else {
    copy.assign(mesh.connectivity.begin(), mesh.connectivity.end());
    eind = copy.data();
  }
  idx_t *xadj = nullptr, *adjncy = nullptr;
  if (METIS_MeshToDual(&n_elements, &n_nodes, eptr.data(), eind, &n_common, &numbering, &xadj, &adjncy) != METIS_OK)
    throw std::runtime_error("METIS_MeshToDual failed");
  Graph g;
  g.vertices = ne;
  g.xadj.assign(xadj, xadj + ne + 1);
  g.adjncy.assign(adjncy, adjncy + xadj[ne]);
  METIS_Free(xadj);
  METIS_Free(adjncy);
  return g;
}

void require_parts_within(int elements, int parts) {
  if (parts > elements)
    throw std::runtime_error("more ranks (" + std::to_string(parts) + ") than elements (" + std::to_string(elements) + ")");
}

}  // namespace

int partition_cluster_size(int elements, int parts) {
  if (elements <= kClusterAbove || parts <= 1) return 1;
  const int size = (elements + kClusterGraph - 1) / kClusterGraph;
  return std::max(1, std::min(size, elements / (kClustersPerPart * parts)));
}

std::vector<int> partition_elements(const mesh::Mesh& mesh, int parts, int cluster_size) {
  const int ne = mesh.element_count();
  std::vector<int> part(static_cast<std::size_t>(ne), 0);
  if (parts <= 1 || ne == 0) return part;
  require_parts_within(ne, parts);
  if (cluster_size <= 0) cluster_size = partition_cluster_size(ne, parts);
  Graph g;
  std::vector<int> cluster_of;  // [element] the graph's vertex, when it is a cluster graph
  if (cluster_size > 1) {
    ElementClusters clusters = cluster_elements(mesh, cluster_size);
    if (clusters.count < parts)
      throw std::runtime_error(std::to_string(clusters.count) + " clusters of elements for " + std::to_string(parts) + " parts");
    g.vertices = clusters.count;
    // Moved where idx_t is int (no second copy of the graph on rank 0), else converted.
    auto take = [](std::vector<int>& from, std::vector<idx_t>& to) {
      if constexpr (std::is_same_v<idx_t, int>)
        to = std::move(from);
      else
        to.assign(from.begin(), from.end());
      from = {};
    };
    take(clusters.offset, g.xadj);
    take(clusters.neighbour, g.adjncy);
    take(clusters.weight, g.edge_weight);
    cluster_of = std::move(clusters.of_element);
    // Vertex weights: the elements of each cluster.
    g.vertex_weight.assign(static_cast<std::size_t>(g.vertices), 0);
    for (int c : cluster_of) ++g.vertex_weight[static_cast<std::size_t>(c)];
  } else {
    g = element_graph(mesh);
  }
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;  // the same partition on every run
  idx_t n_parts = parts, cut = 0;
  std::vector<idx_t> result(static_cast<std::size_t>(g.vertices));
  auto data = [](std::vector<idx_t>& v) { return v.empty() ? nullptr : v.data(); };
  const int status = METIS_PartGraphKway(&g.vertices, &g.constraints, g.xadj.data(), g.adjncy.data(), data(g.vertex_weight),
                                         nullptr, data(g.edge_weight), &n_parts, nullptr, nullptr, options, &cut, result.data());
  if (status != METIS_OK) throw std::runtime_error("METIS_PartGraphKway failed (status " + std::to_string(status) + ")");
  for (int e = 0; e < ne; ++e) part[e] = static_cast<int>(result[cluster_of.empty() ? e : cluster_of[e]]);
  return part;
}

std::vector<int> partition_elements_rcb(const mesh::Mesh& mesh, int parts, const AxisScale& scale) {
  const int ne = mesh.element_count();
  std::vector<int> part(static_cast<std::size_t>(ne), 0);
  if (parts <= 1 || ne == 0) return part;
  require_parts_within(ne, parts);
  const std::vector<double> centre = element_centres<double>(mesh);
  std::vector<int> items(static_cast<std::size_t>(ne));
  std::iota(items.begin(), items.end(), 0);
  bisect_into_parts(items, 0, items.size(), 0, parts, centre, part, scale);
  return part;
}

}  // namespace tribex::solver::parallel
