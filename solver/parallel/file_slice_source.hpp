// SPDX-License-Identifier: MIT
// A mesh file read in slices as an element source of the distributed set-up (element_source.hpp,
// `set-up = distributed`, issue 57 scope 2): no rank reads or holds the whole mesh. The file is any
// mesh::MeshSlices (mesh/mesh_slices.hpp): an Exodus II file (mesh/exodus_slices.hpp)
// or a gmsh MSH 4.1 file (mesh/msh_slices.hpp), whose side sets are quads: match_quads() turns them
// into (element, face) sides in route(), before they are routed as an Exodus file's are.
//
// What each rank reads (for Exodus, the library's partial reads):
//   - the connectivity of its slab of the elements (slab_offsets' even split): 32 B per element;
//   - the coordinates of its even share of the node numbers, the nodes it is "home" to: 24 B per node;
//   - an even share of the entries of every node set and side set.
// Routed once, in route() (two all-to-alls of ints and one sum over the ranks):
//   - every side-set entry (set, position, element, face) to its element's slab rank, which then knows the
//     sides of its elements;
//   - every node-set entry, and every node of a side of a side set that has no node set of its name
//     (read_exodus adds those as node sets: mesh/README.md), to the node's home, which keeps the sets
//     holding each of its nodes (sorted, unique: the serial node set's order and size), and every node of
//     each slab to its home, which so finds the nodes no element uses.
// A rank that needs some elements (its part, or the contact surfaces') asks their slab ranks for their
// nodes and sides, then the nodes' homes for their coordinates and sets (two request-reply all-to-alls):
// the mesh of those elements in split_mesh's layout, the serial part bit for bit.
//
// read_exodus drops the nodes no element uses and numbers the rest in file order: so does route() (the homes
// find them; their used nodes keep their order under new, contiguous ranges; the slabs ask for the new
// numbers: one more request-reply all-to-all, only for such a file).
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mesh/exodus_slices.hpp"
#include "mesh/mesh_slices.hpp"
#include "solver/parallel/element_source.hpp"

namespace tribex::solver::parallel {

class FileSliceSource final : public ElementSource {
 public:
  /// Not collective: opens the file and reads this rank's slab, nodes and set entries. MeshError for a bad
  /// file, thrown by the rank that meets it: the caller agrees on it before route(). `walk_header` false:
  /// the netCDF header's walk (16 MiB read per rank) is left to one rank that opened the file first.
  explicit FileSliceSource(const std::string& path, bool walk_header = true);
  /// The same of any file read in slices (mesh/mesh_slices.hpp: an Exodus or an MSH 4.1 file).
  explicit FileSliceSource(std::unique_ptr<mesh::MeshSlices> file);
  /// Collective over MPI_COMM_WORLD: the routing above.
  void route();

  int element_count() const override { return file_->element_count(); }
  int node_count() const override { return node_count_; }  // the nodes some element uses (read_exodus's)
  const std::vector<mesh::Block>& blocks() const override { return file_->blocks(); }
  std::map<std::string, int> node_set_sizes() const override { return node_set_size_; }
  std::map<std::string, int> side_set_sizes() const override;
  std::vector<int> slab_nodes() const override { return slab_; }
  mesh::Mesh elements_mesh(const std::vector<int>& elements, std::vector<int>& global_node) const override;
  std::vector<int> side_set_elements(const std::vector<std::string>& names) const override;

  /// The nodes of the file no element uses, over all the ranks (after route()): dropped, the others numbered
  /// in file order, as read_exodus does.
  long long unused_nodes() const { return unused_; }
  /// The file's outline (counts, blocks, sets); closed once the constructor has read this rank's share.
  const mesh::MeshSlices& file() const { return *file_; }

 private:
  struct SideEntry {
    int element, set, position, face;  // global element, side set index, position in the set, face 0..5
  };
  void read_set_slices();
  void match_quads();
  void route_sides();
  void route_node_sets();
  void renumber(const std::vector<char>& used);
  void ask_elements(const std::vector<int>& elements, std::vector<int>& conn, std::vector<SideEntry>& sides) const;
  void ask_nodes(const std::vector<int>& global_node, mesh::Mesh& m) const;

  std::unique_ptr<mesh::MeshSlices> file_;
  std::vector<int> element_offset_, node_offset_;  // the even splits (slab_offsets)
  std::vector<int> slab_;                          // [slab element][8] global nodes
  std::vector<double> xyz_;                        // [home node][3], m
  std::vector<SideEntry> sides_;                   // the side-set entries of the slab's elements, by element
  std::vector<std::string> node_set_names_;        // the file's node sets, then those made of side sets
  std::vector<int> member_offset_, member_set_;    // [home node + 1] CSR: the node sets holding it, ascending
  std::map<std::string, int> node_set_size_;
  std::vector<SideEntry> my_sides_;       // this rank's slices of the side sets, until routed
  std::vector<int> my_quads_;             // gmsh: this rank's slices of the side sets' quads (tag, set, 4 nodes)
  std::vector<int> my_set_nodes_;         // this rank's slices of the node sets as (node, set) pairs, until routed
  long long unused_ = 0;
  int node_count_ = 0;
};

}  // namespace tribex::solver::parallel
