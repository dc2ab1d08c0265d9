// SPDX-License-Identifier: MIT
// Results output: one HDF5 file with the heavy arrays plus a small XDMF 2 sidecar that ParaView's
// "XDMF Reader" (Xdmf2) and "Xdmf3ReaderS" open as a time series. See README.md for the layouts.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>
#include <span>
#include <string>

#include "mesh/mesh.hpp"
#include "solver/output/mesh_outline.hpp"

namespace tribex::solver {

/// A field to write: values laid out [entity][components], entity = node or element.
/// components: 1 scalar, 3 vector (x y z), 6 symmetric tensor in Voigt order xx yy zz xy yz zx
/// (written as a full 3x3 "Tensor" because ParaView's two XDMF readers disagree on "Tensor6"),
/// 9 full tensor row-major (xx xy xz yx yy yz zx zy zz); any other count is written as a
/// "Matrix" attribute of that many components.
/// unit: the SI unit of the values ("m", "m/s", "Pa", "1", ...), written as the dataset's `units`
/// attribute and shown in ParaView as "name [unit]"; a field in "m" is written in the file's
/// length unit (ResultsOptions), like the coordinates, so Warp By Vector at scale 1 is right.
struct FieldView {
  std::string name;  // letters, digits, '_', '-', '.'; unique within a step
  int components = 1;
  std::span<const double> values;
  std::string unit;  // empty: none given (the `units` attribute is then empty too)
};

/// How the files are written. The defaults are the deck's (`begin results output`).
struct ResultsOptions {
  std::string length_unit = "auto";  // m, um, nm, or auto (nm under 1 um, um under 1 mm, else m)
  int gzip_level = 1;                // 0: contiguous, uncompressed; 1..9: chunked, shuffle + deflate
  std::string run_id = "";           // the run's identity, root attributes `run_id` and `mesh_sha256` ("" : none);
  std::string mesh_sha256 = "";      // a resumed file of another run is refused
};

/// Parallel runs: the rows of the global node and element arrays this rank writes, as runs
/// {first, count} in ascending order. With a slab every rank constructs the writer and calls
/// write_step (collective, parallel HDF5 with the mpio driver); the FieldView values are then
/// this rank's rows only, packed in run order; rank 0 writes the mesh and the XDMF.
struct ResultsSlab {
  std::vector<std::array<unsigned long long, 2>> node_runs, element_runs;
  long long node_rows = 0, element_rows = 0;  // rows in the runs
};

/// Parallel runs without the whole mesh on any rank: this rank's rows of the mesh arrays, packed in
/// the slab's run order: the owned nodes' coordinates (m, [row][3]) and its elements' connectivity in
/// global node indices ([row][8]). Each rank writes them into its hyperslabs of /mesh, so results.h5
/// holds exactly what a serial run writes.
struct ResultsMeshRows {
  std::vector<double> coordinates;
  std::vector<int> connectivity;
};

/// Writes DIR/results.h5 and DIR/results.xdmf. The mesh is written once; every step references it.
/// After the constructor and after every write_step the pair on disk is complete and readable
/// (HDF5 flushed first, then the XDMF rewritten atomically by temp file + rename), so a crash
/// loses at most the step being written.
class ResultsWriter {
 public:
  /// Creates DIR (and parents) and the two files, truncating old ones; writes coordinates [n][3],
  /// connectivity [e][8] (0-based int32), block_id [e] (-1 for elements in no block) and the block
  /// names. Throws SetupError (one line, path and reason) when a file or directory cannot be made.
  /// resume_time (a restarted run, s): continue DIR/results.h5 when it exists, keeping its steps
  /// before that time and removing the others; SetupError if it is not this mesh's file. A
  /// continued file keeps its own length unit (files without one are in metres).
  ResultsWriter(const std::string& directory, const mesh::Mesh& mesh, const ResultsSlab* slab = nullptr,
                std::optional<double> resume_time = std::nullopt, const ResultsOptions& options = {});
  /// A parallel run's writer from this rank's rows alone (collective, every rank): `outline` the whole
  /// mesh's counts, blocks and resolved length unit (the same on every rank; output::outline_of at
  /// set-up), `rows` this rank's mesh rows in `slab`'s order. No rank needs the whole mesh; the
  /// file is the same as the one the whole-mesh constructor writes. options.length_unit is not used.
  ResultsWriter(const std::string& directory, const output::MeshOutline& outline, const ResultsSlab& slab,
                const ResultsMeshRows& rows, std::optional<double> resume_time = std::nullopt,
                const ResultsOptions& options = {});
  ~ResultsWriter();  // closes; the files stay valid
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  /// Appends one time step (time in s, finite and larger than the previous step's). Every step
  /// must carry the same fields (names, components, order) as the first; a mismatch, a bad name or
  /// a wrong value count throws std::invalid_argument before anything is written. An HDF5 write
  /// failure (disk full) throws std::runtime_error naming the file; earlier steps stay readable.
  void write_step(double time, std::span<const FieldView> nodal, std::span<const FieldView> element);

  /// H5Fflush and XDMF rewrite. write_step already does both; this is for callers that must be
  /// sure before they throw (NumericalFailure) or checkpoint.
  void flush();

  int step_count() const;
  const std::string& length_unit() const;  // "m", "um" or "nm": coordinates and length fields
  const std::string& h5_path() const;
  const std::string& xdmf_path() const;

 private:
  struct Impl;
  struct MeshRows;  // the mesh rows this rank writes (results_writer.cpp)
  std::unique_ptr<Impl> impl_;
  void open(const std::string& directory, const output::MeshOutline& outline, const ResultsSlab* slab,
            std::optional<double> resume_time, const ResultsOptions& options, const MeshRows& rows);
};

}  // namespace tribex::solver
