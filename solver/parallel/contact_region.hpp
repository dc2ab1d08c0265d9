// SPDX-License-Identifier: MIT
// Distributed contact (contact/README.md "Distributed contact", solver/README.md "Parallel runs"):
// each rank runs the contact on its region, the surface nodes it holds plus the ghost nodes within
// ContactManager::region_reach of them, and keeps the contact forces of the nodes it holds. The
// region is a band, not the whole surface: the contact work and the bytes per rank fall with the
// rank count once the contact zone spans several ranks.
//   - refresh (at a step where any pass searches): the ranks exchange the boxes of the surface nodes
//     they hold (MPI_Allgather, six doubles a rank); each rank sends every other rank its owned
//     surface nodes inside that rank's box grown by the reach and not already held there
//     (MPI_Alltoall of the counts, MPI_Alltoallv of the node numbers), and the laws' per-node state
//     of those nodes (the owner's is the reference);
//   - fill_ghosts (every force evaluation): positions, velocities and non-contact forces of the
//     ghost nodes from their owners, point to point into buffers sized at the refresh;
//   - the ContactReductions the manager combines its totals with (MPI_Allreduce).
// Every rank takes part, also one without surface nodes (its box is empty): the totals are wanted on
// rank 0, which writes the history.
#pragma once

#include <mpi.h>

#include <vector>

#include "contact/contact_manager.hpp"
#include "contact/contact_reductions.hpp"

namespace tribex::solver::parallel {

class Domain;

class ContactRegion final : public contact::ContactReductions {
 public:
  /// After Domain::set_surface; `reach` (m) from ContactManager::region_reach.
  ContactRegion(Domain& domain, double reach);

  /// The region of the positions `xg` [surface node][3] (this rank's rows current): ghost lists,
  /// present(), and the laws' state of the nodes sent, from `manager` to the other ranks' managers.
  void refresh(const double* xg, contact::ContactManager& manager);
  /// Ghost rows of xg, vg, fg [surface node][3] from their owners (this rank's own rows current).
  void fill_ghosts(double* xg, double* vg, double* fg);
  /// [surface node] 1 for the nodes of this rank's region (held or ghost).
  const std::vector<char>& present() const { return present_; }
  int ghost_nodes() const { return static_cast<int>(recv_node_.size()); }

  /// The lists of the last refresh, for restart files; restore_lists rebuilds the region from them.
  std::vector<int> lists() const;
  void restore_lists(const std::vector<int>& lists);

  void sum(double* values, int count) override;
  void max(double* values, int count) override;
  void max_at(double* values, int* nodes, int count) override;

 private:
  void exchange_node_numbers();  // receive lists from the send lists
  void size_buffers();
  /// Sends `width` doubles per listed node from `send_` and receives into `recv_`.
  void exchange(int width);

  Domain& domain_;
  double reach_;
  std::vector<double> boxes_;            // [rank][6] min xyz, max xyz of the held surface nodes
  std::vector<int> send_offset_, send_node_;  // [rank + 1], surface nodes this rank sends each rank
  std::vector<int> recv_offset_, recv_node_;  // [rank + 1], ghost nodes from each rank
  std::vector<char> present_;
  std::vector<double> send_, recv_;
  std::vector<MPI_Request> requests_;
  struct Located {
    double value;
    int node;
  };
  std::vector<Located> located_;
};

}  // namespace tribex::solver::parallel
