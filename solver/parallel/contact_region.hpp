// SPDX-License-Identifier: MIT
// Distributed contact (contact/README.md "Distributed contact", solver/README.md "Parallel runs"):
// each rank runs the contact on its region, the surface nodes it holds plus the ghost nodes within
// ContactManager::region_reach of them, and keeps the contact forces of the nodes it holds. The
// region is a band, not the whole surface: the contact work and the bytes per rank fall with the
// rank count once the contact zone spans several ranks.
//   - refresh (at a step where any pass searches), within a sub-communicator of the ranks that hold
//     surface nodes: a grid over their surface nodes with cells of half the reach (at most 64 a
//     side); the ranks exchange the box of their surface nodes and which cells they occupy
//     (MPI_Allgather of six doubles and of a bit set, as OpenRadioss's voxel occupancy), and each
//     rank sends every other rank its owned surface nodes within the reach of that rank's box and
//     within two cells of a cell it occupies, not already held there (sparse_counts of the counts,
//     sparse_alltoallv of the node numbers: sparse_exchange.hpp), with the laws' per-node state of those nodes (the owner's
//     is the reference). The cells because a rank's surface nodes often lie in two patches (a piece
//     of each surface), whose common box would take in much of both surfaces; the box because it is
//     the tighter test where the cells are coarse against the model (small models);
//   - fill_ghosts (every force evaluation): positions of the ghost nodes from their owners, and their
//     velocities and non-contact forces where the passes read them (ContactManager::ghost_fields),
//     point to point into buffers sized at the refresh: every ghost row at a refresh step (the search
//     reads them all), then (trim, owner computes) only the rows the passes read until the next search,
//     the nodes of the candidate faces of the slave nodes the rank projects
//     (ContactManager::rows_read): the region's band is for the search, the rows for the steps;
//   - the ContactReductions the manager combines its totals with (MPI_Allreduce).
// The reductions take every rank (MPI_COMM_WORLD): the totals are wanted on rank 0, which writes the
// history, and by every rank's run guards.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <vector>

#include "contact/contact_manager.hpp"
#include "contact/contact_reductions.hpp"

namespace tribex::solver::parallel {

class Domain;

class ContactRegion final : public contact::ContactReductions {
 public:
  /// After Domain::set_surface. The region's reach is the manager's (ContactManager::region_reach),
  /// read at each refresh.
  explicit ContactRegion(Domain& domain);
  ~ContactRegion() override;
  ContactRegion(const ContactRegion&) = delete;
  ContactRegion& operator=(const ContactRegion&) = delete;

  /// What a ghost row carries besides the position (from the manager, after its distribute).
  void set_fields(contact::ContactManager::GhostFields fields);
  /// The region of the positions `xg` [surface node][3] (this rank's rows current): ghost lists,
  /// present(), and the laws' state of the nodes sent, from `manager` to the other ranks' managers.
  void refresh(const double* xg, contact::ContactManager& manager);
  /// Ghost rows of xg, and of vg and fg where set_fields asked for them, [surface node][3], from their
  /// owners (this rank's own rows current): every ghost row after a refresh, then the rows trim kept.
  void fill_ghosts(double* xg, double* vg, double* fg);
  /// After the search of a refresh step: until the next refresh, fill_ghosts moves only the ghost rows
  /// `read` marks ([surface node], ContactManager::rows_read: what the passes read between searches);
  /// each rank tells the owners which rows it keeps (sparse_counts of the counts, sparse_alltoallv of the
  /// nodes). The other ghosts keep the positions of the refresh, which nothing reads before the next
  /// one refills them all. refresh and restore_lists go back to every row.
  void trim(const std::vector<char>& read);
  /// Owner-computes contact (ContactManager::owner_computes): the parts of a nodal sum, values
  /// [surface node][width] (width <= kMaxSumWidth), that this rank put on its ghost nodes go back to
  /// their owners, who add them to their rows (in member order), then the rows of surface nodes shared
  /// by several ranks are summed over their holders: every rank has the whole sum on the nodes it holds.
  /// Sparse: only the ghost rows with a nonzero bit travel (the contact zone's, not the region's).
  void sum_to_holders(double* values, int width);
  static constexpr int kMaxSumWidth = 4;
  /// [surface node] 1 for the nodes of this rank's region (held or ghost).
  const std::vector<char>& present() const { return present_; }

  /// The lists of the last refresh, for restart files; restore_lists rebuilds the region from them.
  std::vector<int> lists() const;
  void restore_lists(const std::vector<int>& lists);

  void sum(double* values, int count) override;
  void max(double* values, int count) override;
  void max_at(double* values, int* nodes, int count) override;
  /// sum_to_holders, then the owners' sums to the ranks that ghost the nodes.
  void complete_node_sums(double* values, int width) override;

 private:
  void exchange_node_numbers();  // receive lists from the send lists
  void size_buffers();
  void fill_every_row();  // fill lists = the region's lists
  /// Sends `width` doubles per listed node from `send_` and receives into `recv_`, member by member as
  /// the offsets say (the region's lists, or fill_ghosts' trimmed ones).
  void exchange(int width, const std::vector<int>& send_offset, const std::vector<int>& recv_offset);
  /// The rows of `values` [surface node][width] along the send lists to the receive lists (reverse:
  /// the receive lists' rows back along the send lists), only those with a nonzero bit (sparse_rows.hpp):
  /// the receiver adds (reverse) or assigns each listed row's value, +0.0 for a row not sent, in list
  /// order: the dense exchange's bits exactly.
  void exchange_rows(double* values, int width, bool reverse);

  Domain& domain_;
  contact::ContactManager::GhostFields fields_;
  int row_values_ = 9;  // doubles per ghost row: x, and v and f where fields_ asks
  // The ranks holding surface nodes (MPI_COMM_NULL on the others, which have no region); "member" below
  // is a rank of this communicator.
  MPI_Comm comm_ = MPI_COMM_NULL;
  int members_ = 0, me_ = -1;
  std::vector<int> world_rank_;          // [member] its rank in MPI_COMM_WORLD
  std::vector<double> boxes_;            // [member][6] min xyz, max xyz of its surface nodes at the refresh
  std::vector<int> send_offset_, send_node_;  // [member + 1], surface nodes this rank sends each member
  std::vector<int> recv_offset_, recv_node_;  // [member + 1], ghost nodes from each member
  // The rows fill_ghosts moves: the lists above after a refresh, the rows the passes read after trim
  // (subsets in the same order; capacity reserved at the refresh: trim allocates nothing).
  std::vector<int> fill_send_offset_, fill_send_node_, fill_recv_offset_, fill_recv_node_;
  std::vector<char> present_;
  std::vector<double> send_, recv_;
  std::vector<double> rows_send_, rows_recv_;  // [listed node][kMaxSumWidth + 1] of exchange_rows
  std::vector<int> rows_peer_;                 // [request] the member a receive of exchange_rows is from
  std::vector<MPI_Status> statuses_;
  std::vector<double> held_;  // [local node][width] scratch of sum_to_holders (the domain's numbering)
  std::vector<MPI_Request> requests_;
  struct Located {
    double value;
    int node;
  };
  std::vector<Located> located_;
  struct Scratch {  // refresh's working arrays, kept so that a refresh allocates only when they grow
    std::vector<std::uint64_t> mine, occupied;  // occupied cells: this rank's, every member's
    std::vector<int> around, owned_nodes;       // cells near each owned surface node; those nodes
    std::vector<int> send_count, recv_count;    // [member]
  } scratch_;
};

}  // namespace tribex::solver::parallel
