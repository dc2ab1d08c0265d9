// SPDX-License-Identifier: MIT
#include "solver/guards/block_translation.hpp"

#include <algorithm>

#include "solver/model.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {

BlockTranslation::BlockTranslation(const Model& model) : model_(model) {
  // One body per block, except that a surface layer block joins the block it was split from
  // (Model::block_body): a tip and its fully integrated skin translate together, and counting the
  // nodes between them twice would overstate the translation.
  const auto& c = model.mesh.connectivity;
  const std::size_t nb = model.blocks.size();
  nodes_.resize(nb);
  for (std::size_t b = 0; b < nb; ++b) {
    const auto& blk = model.blocks[b];
    const std::size_t body = b < model.block_body.size() ? static_cast<std::size_t>(model.block_body[b]) : b;
    nodes_[body].insert(nodes_[body].end(), c.begin() + 8L * blk.first_element,
                        c.begin() + 8L * (blk.first_element + blk.count));
  }
  for (auto& nodes : nodes_) {
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  }
  sums_.assign(4 * nodes_.size(), 0.0);
}

double BlockTranslation::kinetic_energy(const std::vector<double>& v) {
  const auto& mass = model_.mass;
  const auto& owned = model_.domain.owned;
  std::fill(sums_.begin(), sums_.end(), 0.0);
  for (std::size_t b = 0; b < nodes_.size(); ++b)
    for (int l : nodes_[b]) {
      const double m = owned[static_cast<std::size_t>(l)] * mass[static_cast<std::size_t>(l)];
      for (int i = 0; i < 3; ++i) sums_[4 * b + i] += m * v[3 * static_cast<std::size_t>(l) + i];
      sums_[4 * b + 3] += m;
    }
  parallel::sum(sums_.data(), static_cast<int>(sums_.size()));
  double energy = 0.0;
  for (std::size_t b = 0; b < nodes_.size(); ++b) {
    const double* s = &sums_[4 * b];
    if (s[3] > 0.0) energy += 0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) / s[3];
  }
  return energy;
}

}  // namespace tribex::solver
