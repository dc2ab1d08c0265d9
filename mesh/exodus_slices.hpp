// SPDX-License-Identifier: MIT
// An Exodus II mesh file read in slices (issue 57 scope 2: `set-up = distributed`, no rank holding the
// whole mesh; solver/parallel/file_slice_source.hpp routes the slices between the ranks). The file is opened
// with read_exodus's checks (exodus::open_checked: the netCDF header walked against the file's size,
// HEX8 blocks, the stated limits); then any contiguous range of the elements' connectivity (the netCDF
// hyperslab of each block's `connect` variable, ex_get_partial_conn), of the nodes' coordinates
// (ex_get_partial_coord) and of a set's entries (ex_get_partial_node_set / _side_set) is read alone:
// what a range costs is its own size. Numbers come back 0-based in the file's numbering (elements block
// after block, as read_exodus numbers them) and are checked against the header's counts (MeshError naming
// the file, as read_exodus words it); coordinates in metres (the info records' length unit divided out
// with read_exodus's arithmetic: the same doubles).
//
// What read_exodus does on the whole mesh and a slice cannot: drop the nodes no element uses and renumber
// the others, add a side set's nodes as a node set of its name (file_slice_source.hpp does both by routing),
// validate the elements (the set-up validates each rank's part).
#pragma once

#include <string>
#include <vector>

#include "mesh/exodus_io.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_slices.hpp"

namespace tribex::mesh {

class ExodusSlices final : public MeshSlices {
 public:
  /// MeshError, one line. `walk_header`: as exodus::open_checked's (false: another rank walked this file).
  explicit ExodusSlices(const std::string& path, bool walk_header = true);
  ~ExodusSlices() override;
  ExodusSlices(const ExodusSlices&) = delete;
  ExodusSlices& operator=(const ExodusSlices&) = delete;

  const std::string& path() const override { return path_; }
  int node_count() const override { return h_.nodes; }
  int element_count() const override { return h_.elements; }
  const std::vector<Block>& blocks() const override { return h_.blocks; }
  const exodus::SetOutline& node_sets() const override { return node_sets_; }
  const exodus::SetOutline& side_sets() const override { return side_sets_; }

  /// The 8 nodes of elements [first, first + count), [element][8], 0-based.
  std::vector<int> connectivity(int first, int count) const override;
  /// The coordinates of nodes [first, first + count), [node][3], m.
  std::vector<double> coordinates(int first, int count) const override;
  /// Entries [first, first + count) of node set `set` (index into node_sets()), 0-based nodes, file order.
  std::vector<int> node_set(std::size_t set, long long first, long long count) const override;
  /// Entries [first, first + count) of side set `set`, 0-based (element, face), file order.
  std::vector<Side> side_set(std::size_t set, long long first, long long count) const override;
  /// Closes the file (the library's buffers freed); the outline above stays, the reads throw MeshError.
  void close() override;
  std::unique_ptr<MeshSlices> reopen(bool walk) const override {
    return std::make_unique<ExodusSlices>(path_, walk);
  }

 private:
  std::string path_;
  exodus::Header h_;
  exodus::SetOutline node_sets_, side_sets_;
};

}  // namespace tribex::mesh
