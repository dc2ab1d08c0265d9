// SPDX-License-Identifier: MIT
// One rank's share of a parallel run (physics of the decomposition in solver/README.md
// "Parallel runs"): the elements METIS gave it, the nodes of those elements in local numbering
// (ascending global number), which of them it owns (a node shared by several ranks is owned by the
// lowest), and the communication the time loop needs:
//   - sum_shared: partial nodal forces of shared nodes summed with the neighbour ranks
//     (MPI_Isend/Irecv into buffers sized once), added in ascending rank order on every rank so
//     that all copies of a shared node hold bit-identical sums;
//   - the contact's ghost nodes: ContactRegion (contact_region.hpp) on the surface maps set here;
// results.h5 is written collectively (each rank its owned nodes and its elements, parallel HDF5).
// On one rank every map is the identity and no message is sent.
#pragma once

#include <mpi.h>

#include <vector>

namespace tribex::solver::parallel {

struct MeshPart;

class Domain {
 public:
  int rank = 0, ranks = 1;
  int global_node_count = 0, global_element_count = 0;
  std::vector<int> global_node;     // [local node] global node index
  std::vector<int> global_element;  // [local element] global element index
  std::vector<double> owned;        // [local node] 1 owned here, 0 owned by a lower rank

  bool serial() const { return ranks == 1; }
  /// Wall time spent in sum_shared and the contact region's exchanges (messages and waiting), s; 0 on one rank.
  double communication_seconds = 0.0;
  /// Payload bytes this rank moved in sum_shared and the contact region's ghost exchange since set-up
  /// (summary.json rank_counts): the doubles of each MPI_Isend / MPI_Irecv (the region's refreshes,
  /// at searches, are not counted). Plain increments: nothing allocated in the loop.
  struct Traffic {
    long long halo_sent = 0, halo_received = 0;        // bytes
    long long surface_sent = 0, surface_received = 0;  // bytes of contact ghost rows
    long long halo_exchanges = 0, surface_gathers = 0;  // calls (one per force evaluation; surface: the contact ghost exchanges)
  };
  Traffic traffic;
  /// Nodes held by more than one rank (each holder counts them).
  int shared_node_count() const { return static_cast<int>(halo_.shared_nodes.size()); }
  /// The identity layout of a whole model on one rank (build_model sets it).
  void init_serial(int nodes, int elements);
  /// This rank's layout from its part of the mesh (parallel/mesh_part.hpp): owned flags (the lowest
  /// holder owns a node) and the halo lists of every neighbour rank.
  void init_parallel(const MeshPart& part);
  int owned_node_count() const { return owned_nodes_; }
  /// Local indices of the owned nodes, ascending.
  const std::vector<int>& owned_local_nodes() const { return owned_local_nodes_; }

  /// Sums a nodal [local node][width] vector (width 1..3) over the ranks that share each node.
  void sum_shared(double* nodal, int width = 3);
  /// The same for the contact-surface nodes only (set_surface), [local node][3]; counted as contact
  /// traffic (owner-computes contact: contact_region.hpp).
  void sum_shared_surface(double* nodal, int width = 3);  // width <= 4

  /// Contact surfaces: `surface_nodes` the sorted global nodes of all surfaces (same on every rank),
  /// surface node k = the contact's node k (Model::contact_global_node).
  void set_surface(const std::vector<int>& surface_nodes);
  /// [k] local index of surface node k, -1 when this rank does not hold it.
  const std::vector<int>& surface_local() const { return surface_local_; }
  /// [k] 1 when this rank owns surface node k.
  const std::vector<double>& surface_owned() const { return surface_owned_; }
  /// Whether `other_rank` holds this rank's local node `local_node` too (a neighbour sharing it).
  bool shares_with(int local_node, int other_rank) const;
  /// The local index of global node `global`, -1 when this rank does not hold it (global_node is ascending).
  int local_node(int global) const;

 private:
  int owned_nodes_ = 0;
  /// Shared nodes and their neighbour lists, with the buffers of one exchange.
  struct Halo {
    std::vector<int> neighbours;        // ascending
    std::vector<int> neighbour_offset;  // [k + 1] into neighbour_nodes
    std::vector<int> neighbour_nodes;   // local nodes shared with neighbour k, ascending
    std::vector<int> neighbour_slot;    // their index into shared_nodes
    std::vector<int> shared_nodes;      // local nodes held by more than one rank, ascending
    std::vector<double> send, recv, sum;
    std::vector<MPI_Request> requests;
    void size_buffers(int width = 3);  // doubles per node in a sum
  };
  /// Sums f over `halo`'s shared nodes (in ascending rank order); adds the payload bytes to sent/received.
  void sum_over(Halo& halo, double* f, int width, long long& sent, long long& received);
  Halo halo_;          // every shared node
  Halo surface_halo_;  // the shared contact-surface nodes (set_surface)
  // contact surface maps
  std::vector<int> surface_local_;
  std::vector<double> surface_owned_;
  std::vector<int> owned_local_nodes_;  // ascending
};

}  // namespace tribex::solver::parallel
