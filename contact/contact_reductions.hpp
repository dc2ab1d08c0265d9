// SPDX-License-Identifier: MIT
// What a distributed run lends the contact library (the solver's parallel layer implements it,
// solver/parallel/contact_region.hpp): reductions over the ranks, so that each rank can count only
// the slave nodes it owns and still report the whole interface. The library itself never talks to
// MPI (contact/ depends on mesh/ only). A serial run passes none.
#pragma once

namespace tribex::contact {

class ContactReductions {
 public:
  virtual ~ContactReductions() = default;
  /// values[i] summed over the ranks, in place; every rank gets the same sums.
  virtual void sum(double* values, int count) = 0;
  /// values[i] the largest over the ranks, in place.
  virtual void max(double* values, int count) = 0;
  /// values[i] the largest over the ranks and nodes[i] the node given with it (the lowest node among
  /// equal values), in place.
  virtual void max_at(double* values, int* nodes, int count) = 0;
};

}  // namespace tribex::contact
