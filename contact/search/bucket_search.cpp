// SPDX-License-Identifier: MIT
#include "contact/search/bucket_search.hpp"

#include <algorithm>
#include <cmath>

namespace tribex::contact {

void BucketSearch::find_candidates(const double* x, const ContactSurface& slave, const ContactSurface& master,
                                   double capture, std::vector<int>& offset, std::vector<int>& faces,
                                   const char* present, const char* slaves) {
  if (!slaves) slaves = present;
  const int nf = master.face_count();
  box_.resize(6 * static_cast<std::size_t>(nf));
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  double extent_sum = 0.0;
  int active = 0;  // faces taking part
  auto face_present = [&](int f) {
    const int* fn = &master.face_nodes[4 * f];
    return !present || (present[fn[0]] && present[fn[1]] && present[fn[2]] && present[fn[3]]);
  };
  for (int f = 0; f < nf; ++f) {
    double* b = &box_[6 * f];
    for (int i = 0; i < 3; ++i) {
      b[i] = INFINITY;
      b[3 + i] = -INFINITY;
    }
    if (!face_present(f)) continue;  // an empty box: never binned, never a candidate
    ++active;
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) {
        const double c = x[3 * master.face_nodes[4 * f + a] + i];
        b[i] = std::min(b[i], c);
        b[3 + i] = std::max(b[3 + i], c);
      }
    for (int i = 0; i < 3; ++i) {
      b[i] -= capture;
      b[3 + i] += capture;
      lo[i] = std::min(lo[i], b[i]);
      hi[i] = std::max(hi[i], b[3 + i]);
      extent_sum += b[3 + i] - b[i];
    }
  }
  // Bucket size: the mean inflated box extent, so a box overlaps about 2^dim buckets; grid capped
  // at a few buckets per face so that a sparse surface does not make an enormous grid.
  if (active == 0) {  // none of the master surface here: no candidates
    offset.assign(static_cast<std::size_t>(slave.node_count()) + 1, 0);
    faces.clear();
    return;
  }
  cell_ = extent_sum / (3.0 * active);
  for (int grow = 0; grow < 400; ++grow) {  // bounded (issue 54, item 9): 1.5^400 covers any finite extent
    for (int i = 0; i < 3; ++i) origin_[i] = lo[i];
    nx_ = std::max(1, static_cast<int>(std::ceil((hi[0] - lo[0]) / cell_)));
    ny_ = std::max(1, static_cast<int>(std::ceil((hi[1] - lo[1]) / cell_)));
    nz_ = std::max(1, static_cast<int>(std::ceil((hi[2] - lo[2]) / cell_)));
    if (static_cast<double>(nx_) * ny_ * nz_ <= 8.0 * active + 64) break;
    cell_ *= 1.5;
  }
  auto index = [&](double c, int i, int n) {
    return std::clamp(static_cast<int>((c - origin_[i]) / cell_), 0, n - 1);
  };
  cell_offset_.assign(static_cast<std::size_t>(bucket_count()) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (std::size_t c = 1; c < cell_offset_.size(); ++c) cell_offset_[c] += cell_offset_[c - 1];
      cell_faces_.resize(static_cast<std::size_t>(cell_offset_.back()));
      cursor_.assign(cell_offset_.begin(), cell_offset_.end() - 1);
    }
    for (int f = 0; f < nf; ++f) {
      const double* b = &box_[6 * f];
      if (b[0] > b[3]) continue;  // not present
      const int i0 = index(b[0], 0, nx_), i1 = index(b[3], 0, nx_);
      const int j0 = index(b[1], 1, ny_), j1 = index(b[4], 1, ny_);
      const int k0 = index(b[2], 2, nz_), k1 = index(b[5], 2, nz_);
      for (int k = k0; k <= k1; ++k)
        for (int j = j0; j <= j1; ++j)
          for (int i = i0; i <= i1; ++i) {
            const int cell = (k * ny_ + j) * nx_ + i;
            if (pass == 0) ++cell_offset_[cell + 1];
            else cell_faces_[cursor_[cell]++] = f;
          }
    }
  }
  offset.resize(static_cast<std::size_t>(slave.node_count()) + 1);
  faces.clear();
  offset[0] = 0;
  for (int k = 0; k < slave.node_count(); ++k) {
    const int node = slave.nodes[k];
    const double* p = x + 3 * node;
    const bool outside = (slaves && !slaves[node]) || p[0] < lo[0] || p[0] > hi[0] || p[1] < lo[1] || p[1] > hi[1] || p[2] < lo[2] || p[2] > hi[2];
    if (!outside) {
      const int cell = (index(p[2], 2, nz_) * ny_ + index(p[1], 1, ny_)) * nx_ + index(p[0], 0, nx_);
      for (int c = cell_offset_[cell]; c < cell_offset_[cell + 1]; ++c) {
        const int f = cell_faces_[c];
        const double* b = &box_[6 * f];
        if (p[0] < b[0] || p[0] > b[3] || p[1] < b[1] || p[1] > b[4] || p[2] < b[2] || p[2] > b[5]) continue;
        const int* fn = &master.face_nodes[4 * f];
        if (fn[0] == node || fn[1] == node || fn[2] == node || fn[3] == node) continue;
        faces.push_back(f);
      }
    }
    offset[k + 1] = static_cast<int>(faces.size());
  }
}

}  // namespace tribex::contact
