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
  /// values [node][width] (width <= 4), in the manager's node numbering, hold each rank's part of a
  /// nodal sum (owner computes: the pairs of this rank's slave nodes): afterwards every rank that
  /// holds or ghosts a node has the whole sum there. The tangential pairs' prediction reads the
  /// normal forces and master shares of all pairs this way (node_to_face/tangential_pairs.cpp).
  virtual void complete_node_sums(double* values, int width) = 0;
};

}  // namespace tribex::contact
