// SPDX-License-Identifier: MIT
// The kinetic energy of each element block's mean translation, which the quasi-static guard takes out
// of the kinetic energy: a driven tip moving at constant speed is quasi-static however fast its
// nodes move together; what counts is the motion relative to that (inertia of the deformation).
#pragma once

#include <vector>

namespace tribex::solver {

struct Model;

class BlockTranslation {
 public:
  /// The nodes of each body of `model` (local numbering, each once per body): a block, with any
  /// surface layer blocks split from it (Model::block_body); an empty entry for such a split block.
  explicit BlockTranslation(const Model& model);

  /// sum over bodies b of |sum_I m_I v_I|^2 / (2 sum_I m_I), J, for nodal velocities `v` [node][3],
  /// over all ranks (owned nodes; collective). A node shared by two blocks counts in both.
  double kinetic_energy(const std::vector<double>& v);

 private:
  const Model& model_;
  std::vector<std::vector<int>> nodes_;  // [block] local nodes
  std::vector<double> sums_;             // [block][4]: momentum, mass
};

}  // namespace tribex::solver
