// SPDX-License-Identifier: MIT
// The small-strain guard (issue 51, solver/guards/README.md): a block of the small-strain elastic law
// (`model elastic`, docs/theory.md 2.1) is accurate, and rotation-invariant, only while its strains stay
// small. Every `stride` steps the largest principal strain of those blocks' elements, from their Cauchy
// stress by Hooke's law inverted, is handed to the run guards, which warn once past
// `small_strain_warning`, naming the block and the finite-strain law to use instead.
#pragma once

#include <span>
#include <vector>

#include "solver/element_block.hpp"

namespace tribex::solver {

/// The strain above which a small-strain elastic block warns (dimensionless, largest principal strain).
inline constexpr double small_strain_warning = 0.05;

/// The largest |principal strain| of eps = (sigma - lambda / (3 lambda + 2 mu) tr(sigma) I) / (2 mu), sigma
/// the Cauchy stress in Voigt order xx yy zz xy yz zx (Pa); lambda, mu the Lame constants (Pa).
double largest_principal_strain(const double stress[6], double lambda, double mu);

struct StrainPeak {
  double value = 0.0;  // largest principal strain magnitude
  int element = -1;    // its element, global and 0-based (-1: no small-strain block)
  int block = -1;      // its block (index in the model's blocks)
};

class StrainGuard {
 public:
  /// The small-strain elastic blocks of `blocks`; `global_element` [local element] (empty: serial).
  StrainGuard(std::span<const ElementBlock> blocks, std::vector<int> global_element, long stride = 50);

  bool active() const { return !watched_.empty(); }
  /// Whether step n's element stress is needed (the force pass of step n computes it on request).
  bool due(long n) const { return active() && n % stride_ == 0; }
  /// The largest strain over the watched blocks from their stress of this step, over every rank.
  StrainPeak peak(std::span<const ElementBlock> blocks) const;

 private:
  struct Watched {
    int block;
    double lambda, mu;
  };
  std::vector<Watched> watched_;
  std::vector<int> global_element_;
  long stride_;
};

}  // namespace tribex::solver
