// SPDX-License-Identifier: MIT
// Restart on another rank count (issue 57 scope 4). A restart file holds one group per writing rank,
// each with its arrays in that rank's local numbering and, beside them, the rank's global node and
// element numbers (`global_node`, `global_element`, `block_ranges`). A run resumed on another rank
// count reads the groups it needs and moves every array onto its own partition by global number:
//   - nodal arrays (u, v, a, f, reactions): from the node's owner (the lowest writing rank holding it;
//     every holder has the same bits after the shared-node sum);
//   - element arrays (stress, material state per point: plastic strain, back stress): from the rank that
//     held the element, record by record (plain or four-wide interleaved records, element_block.hpp);
//   - contact arrays, whose numbering (the surface nodes, Model::contact_global_node) is the same on every
//     rank: each row from the owner of its node (positions, forces, traction, status; per pass the gap,
//     the face of the last step, the law's state such as Coulomb's stick points, and the candidate master
//     faces of the last search, so that the next search comes when it would have; the rank's contact
//     region is built anew at the first step (the integrator). Mortar passes search at the first step;
//   - this rank's partial sums that the next step sums over the ranks (the element energies of the
//     last force pass, its viscous power, the plastic work so far): the writers' sum on rank 0, zero on
//     the others, so that the next reduction gives the written total;
//   - the applied loads' nodal forces are re-formed by the integrator from the loads at that time (they
//     are partial sums on shared nodes);
//   - everything else (time, step sizes, energy ledger, totals, schedules, guards) from group 0.
// The same rank count reads its own group as before (bitwise). A file without global numbers (an
// earlier tribex) resumed on another rank count is refused (exit 2) naming the rank count to use.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "solver/restart/state_archive.hpp"

namespace tribex::solver {

/// What a rank's restart group holds and how it maps to global numbers (CentralDifference::restart_layout).
struct RestartLayout {
  std::vector<int> global_node;     // [local node] global node, ascending
  std::vector<int> global_element;  // [local element] global element
  struct Block {
    int first_element = 0, count = 0;  // local elements first_element .. first_element + count - 1
    int state_width = 0;               // doubles of material state per element (0: stateless)
    bool state_interleaved = false;    // records interleaved four elements wide (fully integrated)
  };
  std::vector<Block> blocks;
  std::vector<int> contact_global_node;           // [contact row] global node (every rank the same)
  std::vector<std::vector<int>> pass_slave_rows;  // [pass][slave node] contact row
  std::vector<std::vector<int>> pass_search_rows; // [pass][row of x_at_search] contact row (slave, then master nodes)
  /// Node-to-face passes only: the candidate lists of the last search move with their slave nodes and the
  /// passes search when they would have (else every pass searches at the first step).
  bool keep_candidates = false;
  /// Arrays with one or more values that are this rank's part of a sum over the ranks: (name, index).
  std::vector<std::pair<std::string, int>> partial_sums;
  /// Nodal arrays (3 values per node) taken from the node's owner.
  std::vector<std::string> node_fields;
  /// Nodal arrays the integrator forms again on resume (written as zeros here).
  std::vector<std::string> reformed_node_fields;
  /// Contact arrays with rows in the contact's numbering, taken from the owner of each row's node.
  std::vector<std::string> contact_row_fields;
};

/// The archive of a rank with layout `layout` (rank `rank` of the resumed run) from the groups of a file
/// written by `groups.size()` ranks. `groups[g]` is writer g's archive: with every dataset where this rank
/// needs it (needs_group), else at least its global numbers and its partial sums. Throws SetupError when a
/// node or element of this rank is in no group (another mesh) or an array has an unexpected size.
StateArchive remap_restart(const std::vector<StateArchive>& groups, const RestartLayout& layout, int rank);

/// Which writers' groups this rank reads whole: group 0 (the scalars), the owners of its nodes and of every
/// contact row, the holders of its elements. `ids[g]` holds writer g's global numbers only.
std::vector<char> needs_group(const std::vector<StateArchive>& ids, const RestartLayout& layout);

/// Reads restart file `path` for rank `rank` of `ranks` with `layout`: its own group when the file was
/// written by `ranks` ranks (bitwise the state written), else the groups it needs, remapped
/// (remap_restart). Throws SetupError (exit 2) for a file without global numbers written by another
/// rank count. Makes no MPI call (a run reads restart files in a forked child: isolated_read.hpp).
/// `always_remap` (the test hook TRIBEX_RESTART_REMAP=1 of a run): the same rank count goes through the move
/// too, which must then give bitwise the state written (tests/parallel `*_remapped`).
StateArchive read_restart_for(const std::string& path, const RestartLayout& layout, int rank, int ranks,
                              bool always_remap = false);

}  // namespace tribex::solver
