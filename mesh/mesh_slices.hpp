// SPDX-License-Identifier: MIT
// A mesh file read in slices (issue 57 scope 2: `set-up = distributed`, no rank holding the whole mesh):
// what solver/parallel/file_slice_source.hpp asks of a file, answered by an Exodus II file (exodus_slices.hpp)
// or an MSH 4.1 file (msh_slices.hpp). Numbers are 0-based in the file's numbering: elements in the order
// the serial reader gives them, nodes in the file's order; the source drops the nodes no element uses and
// renumbers the others in that order, as read_exodus and read_gmsh both do.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "mesh/exodus_io.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh {

class MeshSlices {
 public:
  virtual ~MeshSlices() = default;
  virtual const std::string& path() const = 0;
  virtual int node_count() const = 0;
  virtual int element_count() const = 0;
  virtual const std::vector<Block>& blocks() const = 0;
  /// Node sets: an entry is one file record (a node of Exodus's set; a point or line element of gmsh's,
  /// whose nodes node_set returns).
  virtual const exodus::SetOutline& node_sets() const = 0;
  /// Side sets: an entry is one side (Exodus) or one quad (gmsh, matched to its hex's face by the source).
  virtual const exodus::SetOutline& side_sets() const = 0;
  /// The 8 nodes of elements [first, first + count), [element][8].
  virtual std::vector<int> connectivity(int first, int count) const = 0;
  /// The coordinates of nodes [first, first + count), [node][3], m.
  virtual std::vector<double> coordinates(int first, int count) const = 0;
  /// The nodes of entries [first, first + count) of node set `set` (repeats possible: the source sorts).
  virtual std::vector<int> node_set(std::size_t set, long long first, long long count) const = 0;
  /// Entries [first, first + count) of side set `set` as (element, face); MeshError where sides_are_quads().
  virtual std::vector<Side> side_set(std::size_t set, long long first, long long count) const = 0;
  /// True where the side sets are quads to match to hex faces (gmsh): quads() serves them instead.
  virtual bool sides_are_quads() const { return false; }
  /// Entries [first, first + count) of side set `set` as [quad][5]: its element tag, then its 4 nodes in order.
  virtual std::vector<int> quads(std::size_t, long long, long long) const {
    throw MeshError(path() + ": its side sets are no quads");
  }
  /// Closes the file; the outline above stays, the reads throw MeshError.
  virtual void close() = 0;
  /// The same file opened again (for a second pass, e.g. the mesh's hash); `walk` false: a check that
  /// another rank has made may be skipped.
  virtual std::unique_ptr<MeshSlices> reopen(bool walk) const = 0;
};

}  // namespace tribex::mesh
