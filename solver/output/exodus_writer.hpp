// SPDX-License-Identifier: MIT
// Results output in Exodus II (DIR/results.exo), beside or instead of results.h5 + results.xdmf
// (deck: `format = xdmf | exodus | both` in `begin results output`). README.md, "Exodus II output".
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "solver/output/mesh_outline.hpp"
#include "solver/output/results_writer.hpp"
#include "solver/parallel/domain.hpp"

namespace tribex::solver {

/// Writes DIR/results.exo: the mesh (coordinates in the length unit, named HEX8 blocks, node sets, side sets)
/// once, then per step the time, the nodal and element fields (vectors as NAME_x/_y/_z, symmetric
/// tensors as NAME_xx/_yy/_zz/_xy/_yz/_zx, the names ParaView's Exodus reader recombines) and the
/// global variables. 64-bit-offset netCDF (no HDF5 inside). ex_update after every step, so a
/// killed run leaves every completed step readable.
///
/// Parallel runs: one file per rank (the rank-part constructor: each rank writes its part to
/// DIR/results.exo.N.r, joined by `tribex join`; README.md "Exodus II output", "Parallel: one file per
/// rank"); every rank calls write_step (collective). No rank gathers a field.
class ExodusWriter {
 public:
  /// A parallel run's rank: `local` its elements and the nodes they use (local numbering, as `domain`
  /// numbers them), `outline` the whole mesh's counts, blocks and resolved length unit. Collective.
  /// Each rank creates (or, resumed, rewrites as below) DIR/results.exo.N.r; a SetupError is this
  /// rank's alone (the caller agrees on errors afterwards).
  ExodusWriter(const std::string& directory, const mesh::Mesh& local, const parallel::Domain& domain,
               const output::MeshOutline& outline, std::vector<std::string> global_names,
               std::optional<double> resume_time = std::nullopt);
  /// global_names: the global variables written with every step (same order as the values).
  /// Creates DIR and the file (truncating an old one); SetupError (one line, path and reason) when
  /// it cannot. resume_time (a restarted run, s): an existing DIR/results.exo of this mesh is
  /// rewritten with its steps before that time (SetupError if it is another mesh's file).
  /// One rank (the whole mesh). length_unit: m, um, nm or auto (as results.h5's, output/length_unit.hpp):
  /// the coordinates and every field given in "m" are written in it, named in the info records; a
  /// resumed file keeps its own.
  ExodusWriter(const std::string& directory, const mesh::Mesh& mesh, std::vector<std::string> global_names,
               std::optional<double> resume_time = std::nullopt, const std::string& length_unit = "m");
  ~ExodusWriter();  // closes; the file stays valid
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  /// Appends one step (time in s, increasing). The first step's fields (names, components) fix the
  /// file's variables; later steps must carry the same (std::invalid_argument before anything is
  /// written). A write failure throws OutputError naming the file (on every rank).
  void write_step(double time, std::span<const FieldView> nodal, std::span<const FieldView> element,
                  std::span<const double> globals);

  /// ex_update. write_step already does it.
  void flush();

  int step_count() const;
  const std::string& path() const;

  /// The Exodus variable names of one field: NAME (1 component), NAME_x/_y/_z (3), NAME_xx/_yy/
  /// _zz/_xy/_yz/_zx (6, Voigt order), NAME_xx/_xy/_xz/_yx/_yy/_yz/_zx/_zy/_zz (9), else NAME_1..
  static std::vector<std::string> component_names(const std::string& name, int components);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tribex::solver
