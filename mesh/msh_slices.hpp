// SPDX-License-Identifier: MIT
// A gmsh MSH 4.1 file (ASCII or binary) read in slices (mesh_slices.hpp; issue 57 scope 2). gmsh reads
// whole files, so this walks the file itself (the layout of msh_prescan.cpp): the constructor (on one rank;
// the others take its index()) streams it once through a 1 MiB buffer, checking what msh_prescan checks
// (counts, tag ranges, section ends: MeshError "PATH: byte N: ...") and keeping only an index: each
// entity's physical groups, and the byte offset, count and tags of each entity block of $Nodes and
// $Elements. A range of elements or nodes is then read alone from those offsets (binary: one seek; ASCII:
// a seek to the mark the walk noted every 4,096 entries, then at most 4,095 entries skipped).
//
// What read_gmsh (gmsh_io.cpp) makes, this gives in the same numbering: blocks from the 3-D physical groups
// by tag (or one "block_1"), each block's hexes by element tag; nodes by tag, those no hex uses dropped by
// the source; node sets from the 0-D/1-D groups (their elements' nodes) and side sets from the 2-D groups'
// quads (matched to hex faces by the source, which adds their nodes as node sets as read_gmsh does).
// Files this does not slice say why in `unsupported()` (the set-up then reads them serially, whose reader
// gives any error they hold): MSH 2.2, partitioned files, node tags that are not one contiguous run per
// entity block covering 1..N, a block's hexes whose tags are not ascending runs, non-hex volume or non-quad
// surface elements, an entity in two physical volumes, hexes in no physical volume, two sets of one name.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mesh/mesh_slices.hpp"

namespace tribex::mesh {

class MshSlices final : public MeshSlices {
 public:
  /// Walks the file (MeshError for a corrupt one), holding only the index.
  explicit MshSlices(const std::string& path);
  /// The index of a walk of the same file elsewhere (index() of another rank's MshSlices): no walk.
  MshSlices(const std::string& path, const std::string& index);
  /// The index as bytes (for MshSlices(path, index) on the other ranks: one rank walks the file, not P).
  std::string index() const;
  /// Why the file cannot be read in slices ("" when it can); the reads below need it empty.
  const std::string& unsupported() const { return unsupported_; }

  const std::string& path() const override { return path_; }
  int node_count() const override { return node_count_; }
  int element_count() const override { return element_count_; }
  const std::vector<Block>& blocks() const override { return blocks_; }
  const exodus::SetOutline& node_sets() const override { return node_sets_; }
  const exodus::SetOutline& side_sets() const override { return side_sets_; }
  std::vector<int> connectivity(int first, int count) const override;
  std::vector<double> coordinates(int first, int count) const override;
  std::vector<int> node_set(std::size_t set, long long first, long long count) const override;
  std::vector<Side> side_set(std::size_t set, long long first, long long count) const override;
  bool sides_are_quads() const override { return true; }
  std::vector<int> quads(std::size_t set, long long first, long long count) const override;
  void close() override {}
  std::unique_ptr<MeshSlices> reopen(bool) const override { return std::make_unique<MshSlices>(*this); }

  /// One entity block of $Nodes or $Elements.
  struct EntityBlock {
    int dim = 0, entity = 0, type = 0;  // type: the element type ($Elements) or 0
    int per = 0;                         // $Elements: nodes per element; $Nodes: doubles per node (3 + u v w)
    long long n = 0;                     // entries
    std::int64_t at = 0;                 // byte offset of the first entry ($Nodes: of the coordinates)
    long long first_tag = 0, last_tag = 0;
    bool ascending = true;  // tags ascending by one ($Nodes) or ascending ($Elements)
    long long mark = 0;     // ASCII: its first entry in marks_ (the offset of every kMarkEvery-th entry)
  };

 private:
  struct Group {
    int dim = 0, tag = 0;
    std::string name;
    std::vector<std::size_t> blocks;  // its element blocks (indices into elements_), in file order
  };
  template <class Archive>
  void fields(Archive& a);
  void index(const std::vector<Group>& groups);
  void index_volumes(std::vector<Group> volumes);
  void index_sets(const std::vector<Group>& groups, int dim, exodus::SetOutline& sets,
                  std::vector<std::vector<std::size_t>>& blocks);
  // Entries [first, first + count) of the concatenated element blocks `blocks`, [entry][1 + per] (tag, nodes).
  std::vector<long long> read_elements(const std::vector<std::size_t>& blocks, long long first, long long count) const;

  std::string path_, unsupported_;
  bool binary_ = false;
  int node_count_ = 0, element_count_ = 0;
  std::vector<EntityBlock> nodes_, elements_;  // $Nodes' blocks by first tag; $Elements' in file order
  std::vector<std::int64_t> marks_;            // ASCII: byte offsets of every kMarkEvery-th entry of each block
  std::vector<std::size_t> hexes_;             // the hex blocks in the serial order
  std::vector<long long> hex_first_;           // [hexes_ + 1] the first element of each
  std::vector<Block> blocks_;
  exodus::SetOutline node_sets_, side_sets_;
  std::vector<std::vector<std::size_t>> node_set_blocks_, side_set_blocks_;
};

}  // namespace tribex::mesh
