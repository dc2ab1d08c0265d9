// SPDX-License-Identifier: MIT
// Broad phase of the contact search (docs/theory.md 5.1, global phase): axis-aligned boxes of the
// master faces, inflated by the capture distance, binned in a uniform grid of buckets; each slave
// node is tested against the boxes of its bucket. Output: the candidate faces of every slave node
// (CSR). Storage is reused between builds (no allocation once capacities have grown).
#pragma once

#include <vector>

#include "contact/surface.hpp"

namespace tribex::contact {

class BucketSearch {
 public:
  /// Candidates of every node of `slave` among the faces of `master` at positions `x` [node][3]:
  /// faces whose box, inflated by `capture` (m), contains the node. A face touching the node itself
  /// is never a candidate (self-contact of one surface). `present` [node] (nullptr: every node): only
  /// faces whose four nodes are present take part (a distributed run's region), and only slave nodes
  /// with `slaves` [node] nonzero (nullptr: the present ones).
  void find_candidates(const double* x, const ContactSurface& slave, const ContactSurface& master, double capture,
                       std::vector<int>& offset, std::vector<int>& faces, const char* present = nullptr,
                       const char* slaves = nullptr);

  int bucket_count() const { return nx_ * ny_ * nz_; }

 private:
  std::vector<double> box_;        // [face][6] min xyz, max xyz (inflated)
  std::vector<int> cell_offset_;   // [cell + 1]
  std::vector<int> cell_faces_;
  std::vector<int> cursor_;
  double origin_[3] = {0, 0, 0};
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1, nz_ = 1;
};

}  // namespace tribex::contact
