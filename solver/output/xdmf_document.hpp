// SPDX-License-Identifier: MIT
// The XDMF 2 sidecar as text: a spatial collection holding one temporal collection per element
// block, named after the block (ParaView lists the blocks by name and can hide or extract each),
// each with one Uniform grid per step. A block grid's Topology and cell attributes are HyperSlabs
// of the whole-mesh arrays (blocks are contiguous element ranges); its Geometry and nodal
// attributes are the whole node arrays, so the block topology indexes global nodes and every
// nodal array is written once. A block's first step grid holds its mesh DataItems; every later
// step pulls the same elements in with xi:include (XPointer), so the mesh appears once in the XML
// and once in the HDF5 file. Before the first step the document is one spatial collection of the
// block grids with the mesh alone, so ParaView can already show it.
#pragma once

#include <string>
#include <vector>

namespace tribex::solver::output {

enum class Center { node, cell };

/// One attribute of a step as XDMF sees it (components as stored in the HDF5 file).
struct XdmfAttribute {
  std::string name;
  Center center = Center::node;
  int components = 1;
  std::string h5_dataset;  // absolute path inside the HDF5 file
  std::string unit;        // the values' unit, an <Information Name="units"> of the attribute (empty: none)
};

/// A grid: the elements [first, first + count) of the mesh, all of one block.
struct XdmfBlock {
  std::string name;
  long long first = 0;
  long long count = 0;
};

class XdmfDocument {
 public:
  /// h5_file_name: the HDF5 file name relative to the XDMF file (same directory). blocks: the
  /// grids, in element order, covering every element; length_unit: the unit of the geometry.
  XdmfDocument(std::string h5_file_name, long long node_count, long long element_count,
               std::vector<XdmfBlock> blocks, std::string length_unit = "m");

  void add_step(double time, const std::vector<XdmfAttribute>& attributes);
  int step_count() const { return step_count_; }
  /// A resumed run adopts the unit of the file it continues (set before the first add_step).
  void set_length_unit(std::string unit) { length_unit_ = std::move(unit); }

  /// The whole document.
  std::string text() const;

  /// Writes text() to `path` + ".tmp" and renames it over `path`, so a reader (or a crash) never
  /// sees a half-written document. Throws std::runtime_error naming the path on failure.
  void write_atomically(const std::string& path) const;

  /// Grid name of step k ("step_000000"): also the HDF5 group name under /steps.
  static std::string step_name(int k);

 private:
  // Topology, Geometry and block_id of block b.
  std::string mesh_elements(std::size_t b, const std::string& indent) const;
  // A whole HDF5 dataset, or (block != nullptr) the rows of that block.
  std::string h5_item(const std::string& dataset, long long rows, int cols, bool integer,
                      const XdmfBlock* block = nullptr) const;
  // The grid of block b at a step (with_time) or of the mesh alone (named after the block).
  std::string block_grid(std::size_t b, int step, double time, const std::vector<XdmfAttribute>& attributes,
                         bool with_time) const;

  std::string h5_file_;
  long long nodes_;
  long long elements_;
  std::vector<XdmfBlock> blocks_;
  std::string length_unit_;
  std::vector<std::string> steps_xml_;  // per block: its step grids written so far
  int step_count_ = 0;
};

}  // namespace tribex::solver::output
