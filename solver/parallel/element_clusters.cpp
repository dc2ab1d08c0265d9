// SPDX-License-Identifier: MIT
#include "solver/parallel/element_clusters.hpp"

#include <algorithm>
#include <numeric>
#include <utility>

#include "solver/parallel/coordinate_split.hpp"

namespace tribex::solver::parallel {
namespace {

// k-d tree leaves over the element centroids, numbered left to right; `order` ends grouped by leaf.
void split_into_leaves(const mesh::Mesh& mesh, int size, std::vector<int>& order, ElementClusters& out) {
  const int ne = mesh.element_count();
  const std::vector<float> centre = element_centres<float>(mesh);  // single precision: 12 B per element
  order.resize(static_cast<std::size_t>(ne));
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::pair<int, int>> stack{{0, ne}};
  while (!stack.empty()) {
    const auto [begin, end] = stack.back();
    stack.pop_back();
    if (end - begin <= size) {
      for (int k = begin; k < end; ++k) out.of_element[order[k]] = out.count;
      ++out.count;
      continue;
    }
    const int mid = begin + (end - begin) / 2;
    split_along_longest_side(order, static_cast<std::size_t>(begin), static_cast<std::size_t>(mid),
                             static_cast<std::size_t>(end), centre);
    stack.emplace_back(mid, end);    // right, taken second
    stack.emplace_back(begin, mid);  // left, taken first: leaves numbered left to right
  }
}

}  // namespace

ElementClusters cluster_elements(const mesh::Mesh& mesh, int size) {
  const int ne = mesh.element_count(), nn = mesh.node_count();
  ElementClusters out;
  out.of_element.assign(static_cast<std::size_t>(ne), 0);
  std::vector<int> order;
  split_into_leaves(mesh, std::max(size, 1), order, out);
  // Cluster by cluster (order is grouped by cluster, ascending): each node belongs to the first
  // cluster that reaches it; a later cluster reaching it records an edge to that one. So every edge is
  // found once, from its higher cluster: `lower` holds each cluster's edges to lower clusters.
  std::vector<int> first_cluster(static_cast<std::size_t>(nn), -1);
  std::vector<int> lower_offset(static_cast<std::size_t>(out.count) + 1, 0);
  std::vector<std::pair<int, int>> lower;  // (neighbour, weight)
  std::size_t k = 0;
  for (int c = 0; c < out.count; ++c) {
    const std::size_t begin = lower.size();
    auto add = [&](int other, int w) {
      for (std::size_t j = begin; j < lower.size(); ++j)
        if (lower[j].first == other) {
          lower[j].second += w;
          return;
        }
      lower.emplace_back(other, w);
    };
    for (; k < order.size() && out.of_element[order[k]] == c; ++k) {
      const int e = order[k];
      for (int a = 0; a < 8; ++a) {
        int& first = first_cluster[mesh.connectivity[8 * static_cast<std::size_t>(e) + a]];
        if (first < 0)
          first = c;
        else if (first != c)
          add(first, 1);
      }
    }
    lower_offset[c + 1] = static_cast<int>(lower.size());
  }
  first_cluster = {};
  order = {};
  // Both directions.
  out.offset.assign(static_cast<std::size_t>(out.count) + 1, 0);
  for (int c = 0; c < out.count; ++c)
    for (int j = lower_offset[c]; j < lower_offset[c + 1]; ++j) {
      ++out.offset[c + 1];
      ++out.offset[lower[j].first + 1];
    }
  for (int c = 0; c < out.count; ++c) out.offset[c + 1] += out.offset[c];
  out.neighbour.assign(static_cast<std::size_t>(out.offset[out.count]), 0);
  out.weight.assign(out.neighbour.size(), 0);
  std::vector<int> fill(out.offset.begin(), out.offset.end() - 1);
  for (int c = 0; c < out.count; ++c)
    for (int j = lower_offset[c]; j < lower_offset[c + 1]; ++j) {
      const auto [other, w] = lower[j];
      out.neighbour[fill[c]] = other;
      out.weight[fill[c]++] = w;
      out.neighbour[fill[other]] = c;
      out.weight[fill[other]++] = w;
    }
  return out;
}

}  // namespace tribex::solver::parallel
