// SPDX-License-Identifier: MIT
// The XDMF 2 sidecar as text: a temporal collection of Uniform grids. The first step's grid holds
// the Topology, Geometry and block_id DataItems that point into the HDF5 file; every later step
// pulls those same elements in with xi:include (XPointer), so the mesh appears once in the XML
// and once in the HDF5 file. Before the first step the document is a single Uniform grid with the
// mesh alone, so ParaView can already show it.
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
};

class XdmfDocument {
 public:
  /// h5_file_name: the HDF5 file name relative to the XDMF file (same directory).
  XdmfDocument(std::string h5_file_name, long long node_count, long long element_count,
               std::vector<std::string> block_names);

  void add_step(double time, const std::vector<XdmfAttribute>& attributes);
  int step_count() const { return step_count_; }

  /// The whole document.
  std::string text() const;

  /// Writes text() to `path` + ".tmp" and renames it over `path`, so a reader (or a crash) never
  /// sees a half-written document. Throws std::runtime_error naming the path on failure.
  void write_atomically(const std::string& path) const;

  /// Grid name of step k ("step_000000"): also the HDF5 group name under /steps.
  static std::string step_name(int k);

 private:
  std::string mesh_elements(const std::string& indent) const;  // Topology, Geometry, block_id
  std::string h5_item(const std::string& dataset, long long rows, int cols, bool integer) const;

  std::string h5_file_;
  long long nodes_;
  long long elements_;
  std::vector<std::string> block_names_;
  std::string steps_xml_;  // the step grids written so far
  int step_count_ = 0;
};

}  // namespace tribex::solver::output
