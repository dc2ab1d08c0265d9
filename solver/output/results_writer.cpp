// SPDX-License-Identifier: MIT
#include "solver/output/results_writer.hpp"

#include <hdf5.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <vector>

#include "solver/errors.hpp"
#include "solver/output/h5_handles.hpp"
#include "solver/output/length_unit.hpp"
#include "solver/output/mesh_outline.hpp"
#include "solver/output/row_blocks.hpp"
#include "solver/output/xdmf_document.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {
namespace {

// HDF5 1.10.8 with chunked (compressed) datasets: when the disk fills, the failed metadata flush
// leaves the file's cache half-flushed ("slist already enabled?"), H5Fclose fails, and HDF5's own
// exit handler then closes the file again and crashes (SIGSEGV instead of exit code 3,
// cli_disk_full). Every file tribex opens is closed by its RAII handle and flushed after every
// step, so the handler has nothing to do: it is switched off before HDF5 initialises (static
// initialisation, before main; H5dont_atexit has no effect once the library is up).
[[maybe_unused]] const bool hdf5_exit_handler_off = (H5dont_atexit(), true);

using output::Center;
using output::H5Handle;
using output::QuietHdf5Errors;

struct FieldSpec {
  std::string name;
  int components = 0;  // as stored (stored_components): what a resumed run reads back from the file
  friend bool operator==(const FieldSpec&, const FieldSpec&) = default;
};

bool valid_name(const std::string& n) {
  if (n.empty() || n == "block_id") return false;
  for (char c : n) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return n != "." && n != "..";
}

// Stored components: a symmetric tensor (6, Voigt xx yy zz xy yz zx) is stored as the full 3x3.
int stored_components(int components) { return components == 6 ? 9 : components; }

// Voigt index of full-tensor entry (i, j), row-major: xx xy xz / yx yy yz / zx zy zz.
constexpr int voigt_of_full[9] = {0, 3, 5, 3, 1, 4, 5, 4, 2};

// The XDMF grids: one per block (blocks are contiguous element ranges), in element order; a run of
// elements in no block (block_id -1) gets a grid "no_block", so every element is in one grid.
std::vector<output::XdmfBlock> grid_ranges(const std::vector<mesh::Block>& mesh_blocks, long long elements) {
  std::vector<output::XdmfBlock> blocks;
  for (const auto& b : mesh_blocks)
    if (b.element_count > 0) blocks.push_back({b.name, b.first_element, b.element_count});
  std::sort(blocks.begin(), blocks.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  std::vector<output::XdmfBlock> grids;
  long long next = 0;
  for (const auto& b : blocks) {
    if (b.first > next) grids.push_back({"no_block", next, b.first - next});
    if (b.first < next) return {{"mesh", 0, elements}};  // overlapping blocks: one grid, block_id tells them apart
    grids.push_back(b);
    next = b.first + b.count;
  }
  if (next < elements) grids.push_back({"no_block", next, elements - next});
  return grids;
}

// The mpio driver with a 4 MiB collective buffer per aggregator (MPI-IO hint `cb_buffer_size`). Open MPI's
// OMPIO (fcoll vulcan) otherwise holds 32 MiB on every aggregator rank in each collective write, rank 0 among
// them: with the writes in blocks (row_blocks.hpp) that buffer was the largest single allocation of rank 0's
// peak in a 64-rank run of the 4 M-element counts model (heaptrack: 33.6 MB in
// mca_fcoll_vulcan_file_write_all). A hint changes how the bytes reach the file, not which bytes: more,
// smaller write cycles per aggregator (docs/measurements/2026-11-29-output-memory.md).
void set_collective_buffer(hid_t fapl) {
  MPI_Info info = MPI_INFO_NULL;
  MPI_Info_create(&info);
  MPI_Info_set(info, "cb_buffer_size", "4194304");
  H5Pset_fapl_mpio(fapl, MPI_COMM_WORLD, info);  // HDF5 keeps its own copy of the info
  MPI_Info_free(&info);
}

}  // namespace

struct ResultsWriter::Impl {
  std::string directory;
  std::string h5_path;
  std::string xdmf_path;
  long long nodes = 0;
  long long elements = 0;
  H5Handle file;
  output::LengthUnit unit;  // of coordinates and of every field given in metres
  int gzip_level = 1;
  output::XdmfDocument doc;
  std::vector<FieldSpec> nodal_spec;
  std::vector<FieldSpec> element_spec;
  std::vector<double> tensor_buffer;  // reused every step: full tensors expanded from Voigt
  std::vector<double> scaled_buffer;  // reused every step: a length field in the file's unit
  double last_time = 0.0;
  // Parallel: this rank's rows (runs) and whether it is rank 0.
  bool parallel = false, root = true;
  long long node_rows = 0, element_rows = 0;
  // Parallel: this rank's rows are exchanged into a block of consecutive rows before each write
  // (row_blocks.hpp), one plan for the nodes and one for the elements, built at set-up; the selections of
  // the block, one per (nodal, columns), built at set-up for the shapes the fields have (1, 3, 9 columns)
  // and reused by every step (selection()).
  std::optional<output::RowBlocks> node_blocks, element_blocks;
  std::vector<std::pair<std::array<hsize_t, 2>, output::RowSelection>> selections;

  Impl(std::string dir, long long n, long long e, std::vector<output::XdmfBlock> grids, output::LengthUnit length,
       int gzip)
      : directory(std::move(dir)),
        h5_path((std::filesystem::path(directory) / "results.h5").string()),
        xdmf_path((std::filesystem::path(directory) / "results.xdmf").string()),
        nodes(n),
        elements(e),
        unit(std::move(length)),
        gzip_level(gzip),
        doc("results.h5", n, e, std::move(grids), unit.name) {}

  // The unit a field is stored in: the length unit for fields in metres, else the field's own.
  std::string stored_unit(const std::string& field_unit) const { return field_unit == "m" ? unit.name : field_unit; }

  void check_fields(std::span<const FieldView> fields, long long entities, const char* kind,
                    const std::vector<FieldSpec>& spec, std::set<std::string>& seen) const;
  void write_field(hid_t group, const FieldView& f, long long entities, const std::string& path, bool nodal);
  bool open_for_resume(hid_t fapl, double resume_time);
  // The constructor's steps: the folder and the file can be made (rank 0 probes, every rank learns the
  // outcome); the /mesh group of a new file.
  void check_can_create(bool resume);
  void write_mesh(const MeshRows& rows, const std::vector<mesh::Block>& blocks, const ResultsOptions& options);
  // The selection of this rank's rows of a nodal or element dataset of `cols` columns (0: scalar).
  const output::RowSelection& selection(bool nodal, hsize_t cols);
};

// The mesh rows a rank writes: every row in a serial run, rank 0's whole mesh or nothing in the
// whole-mesh parallel constructor, the rank's own rows (the slab's runs) in the distributed one.
struct ResultsWriter::MeshRows {
  const double* coordinates = nullptr;  // m, [row][3], packed in node_runs order
  const int* connectivity = nullptr;    // global node indices, [row][8], packed in element_runs order
  std::vector<std::array<hsize_t, 2>> node_runs, element_runs;
  long long node_rows = 0, element_rows = 0;  // rows in the runs
};

const output::RowSelection& ResultsWriter::Impl::selection(bool nodal, hsize_t cols) {
  const std::array<hsize_t, 2> key{nodal ? 1u : 0u, cols};
  for (const auto& [k, s] : selections)
    if (k == key) return s;
  // A shape first met in the loop (a Matrix field of another width): built once, then kept.
  const output::RowBlocks& b = nodal ? *node_blocks : *element_blocks;
  selections.emplace_back(key, output::select_row_block(static_cast<hsize_t>(nodal ? nodes : elements), cols, b.first(),
                                                        b.count(), h5_path));
  return selections.back().second;
}

namespace {

// Rows and columns of a dataset (columns 0 for a one-dimensional one); {-1, -1} if it is not there.
std::array<long long, 2> dataset_shape(hid_t loc, const std::string& path) {
  if (H5Lexists(loc, path.c_str(), H5P_DEFAULT) <= 0) return {-1, -1};
  H5Handle d(H5Dopen2(loc, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!d.valid()) return {-1, -1};
  H5Handle space(H5Dget_space(d.get()), H5Sclose);
  hsize_t dims[2] = {0, 0};
  const int rank = space.valid() ? H5Sget_simple_extent_dims(space.get(), dims, nullptr) : -1;
  if (rank == 1) return {static_cast<long long>(dims[0]), 0};
  if (rank == 2) return {static_cast<long long>(dims[0]), static_cast<long long>(dims[1])};
  return {-1, -1};
}

// Names of the links in a group in the order they were made (in name order for a group that did
// not track it: files written before the order was recorded).
std::vector<std::string> link_names(hid_t group) {
  std::vector<std::string> names;
  const auto collect = [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
    static_cast<std::vector<std::string>*>(out)->push_back(name);
    return 0;
  };
  if (H5Literate(group, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, collect, &names) < 0) {
    names.clear();
    H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names);
  }
  return names;
}

// Field lists compare as sets: a resumed run may rebuild the earlier steps' list in name order.
bool same_fields(std::vector<FieldSpec> a, std::vector<FieldSpec> b) {
  const auto by_name = [](const FieldSpec& x, const FieldSpec& y) { return x.name < y.name; };
  std::sort(a.begin(), a.end(), by_name);
  std::sort(b.begin(), b.end(), by_name);
  return a == b;
}

}  // namespace

// A restarted run continues the results.h5 already in its output folder: the steps before the
// restart time are kept, the later ones (the stopped run's last state, or steps of a run that
// went on past its restart file and then failed) are unlinked, and the XDMF is rebuilt from what
// is left. Returns false when there is no results.h5 to continue (a new one is then created).
bool ResultsWriter::Impl::open_for_resume(hid_t fapl, double resume_time) {
  if (!std::filesystem::exists(h5_path)) return false;
  file = H5Handle(H5Fopen(h5_path.c_str(), H5F_ACC_RDWR, fapl), H5Fclose);
  const hid_t f = file.get();
  const bool matches = file.valid() && dataset_shape(f, "/mesh/coordinates") == std::array<long long, 2>{nodes, 3} &&
                       dataset_shape(f, "/mesh/connectivity") == std::array<long long, 2>{elements, 8} &&
                       H5Lexists(f, "/steps", H5P_DEFAULT) > 0;
  if (!matches)
    throw SetupError("cannot continue '" + h5_path + "': it is not the results file of this mesh (" +
                     std::to_string(nodes) + " nodes, " + std::to_string(elements) +
                     " elements); move it away or resume into another output folder (-o)");
  // The file keeps its unit: files written before the unit was recorded are in metres.
  const std::string file_unit = output::read_string_attribute(f, "length_unit");
  try {
    unit = output::length_unit_named(file_unit.empty() ? "m" : file_unit);
  } catch (const std::invalid_argument&) {
    throw SetupError("cannot continue '" + h5_path + "': its length_unit '" + file_unit + "' is not m, um or nm");
  }
  doc.set_length_unit(unit.name);
  H5Handle steps(H5Gopen2(f, "/steps", H5P_DEFAULT), H5Gclose);
  for (int k = 0;; ++k) {
    const std::string name = output::XdmfDocument::step_name(k);
    if (H5Lexists(steps.get(), name.c_str(), H5P_DEFAULT) <= 0) break;
    H5Handle g(H5Gopen2(steps.get(), name.c_str(), H5P_DEFAULT), H5Gclose);
    double time = NAN;
    H5Handle attr(H5Aopen(g.get(), "time", H5P_DEFAULT), H5Aclose);
    if (!attr.valid() || H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &time) < 0)
      throw SetupError("cannot continue '" + h5_path + "': step '" + name + "' has no time; move the file away");
    // Kept: the steps before the restart time. The step at it (written by the stopped run as its
    // last state) is written again by the resumed run when its schedule has one there, as
    // history.csv's row (HistoryWriter keeps the rows before the restart step).
    if (!(time < resume_time) || (doc.step_count() > 0 && !(time > last_time))) {
      g.reset();
      attr.reset();
      for (int j = k;; ++j) {  // this step and every later one
        const std::string later = output::XdmfDocument::step_name(j);
        if (H5Lexists(steps.get(), later.c_str(), H5P_DEFAULT) <= 0) break;
        if (H5Ldelete(steps.get(), later.c_str(), H5P_DEFAULT) < 0)
          throw SetupError("cannot continue '" + h5_path + "': HDF5 could not remove step '" + later + "'");
      }
      break;
    }
    std::vector<output::XdmfAttribute> attributes;
    std::vector<FieldSpec> nodal, element;
    for (const char* kind : {"nodal", "element"}) {
      if (H5Lexists(g.get(), kind, H5P_DEFAULT) <= 0) continue;
      H5Handle sub(H5Gopen2(g.get(), kind, H5P_DEFAULT), H5Gclose);
      const bool is_nodal = kind[0] == 'n';
      for (const std::string& field : link_names(sub.get())) {
        const auto shape = dataset_shape(sub.get(), field);
        const int stored = shape[1] == 0 ? 1 : static_cast<int>(shape[1]);
        const std::string path = "/steps/" + name + "/" + kind + "/" + field;
        H5Handle d(H5Dopen2(sub.get(), field.c_str(), H5P_DEFAULT), H5Dclose);
        const std::string field_unit = d.valid() ? output::read_string_attribute(d.get(), "units") : std::string();
        attributes.push_back({field, is_nodal ? Center::node : Center::cell, stored, path, field_unit});
        (is_nodal ? nodal : element).push_back({field, stored});
      }
    }
    if (doc.step_count() == 0) {
      nodal_spec = nodal;
      element_spec = element;
    }
    doc.add_step(time, attributes);
    last_time = time;
  }
  return true;
}

void ResultsWriter::Impl::check_fields(std::span<const FieldView> fields, long long entities,
                                       const char* kind, const std::vector<FieldSpec>& spec,
                                       std::set<std::string>& seen) const {
  const std::string where = "ResultsWriter::write_step (" + h5_path + "): " + kind + " field ";
  for (const auto& f : fields) {
    if (!valid_name(f.name))
      throw std::invalid_argument(where + "'" + f.name +
                                  "': name must be non-empty letters, digits, '_', '-', '.' and not block_id");
    if (!seen.insert(f.name).second)
      throw std::invalid_argument(where + "'" + f.name + "' appears twice in one step");
    if (f.components < 1)
      throw std::invalid_argument(where + "'" + f.name + "' has " + std::to_string(f.components) +
                                  " components; need at least 1");
    const auto expected = static_cast<std::size_t>(entities) * static_cast<std::size_t>(f.components);
    if (f.values.size() != expected)
      throw std::invalid_argument(where + "'" + f.name + "' has " + std::to_string(f.values.size()) +
                                  " values; expected " + std::to_string(entities) + " x " +
                                  std::to_string(f.components) + " = " + std::to_string(expected));
  }
  if (doc.step_count() == 0) return;
  std::vector<FieldSpec> given;
  for (const auto& f : fields) given.push_back({f.name, stored_components(f.components)});
  if (!same_fields(spec, given))
    throw std::invalid_argument(where + "list differs from the first step's; every step must write the "
                                        "same fields (names and components)");
}

void ResultsWriter::Impl::write_field(hid_t group, const FieldView& f, long long entities,
                                      const std::string& path, bool nodal) {
  const int stored = stored_components(f.components);
  const auto rows = static_cast<hsize_t>(entities);
  if (parallel) entities = nodal ? node_rows : element_rows;  // values hold this rank's rows only
  const auto cols = static_cast<hsize_t>(stored == 1 ? 0 : stored);  // scalars are 1-D [entity]
  H5Handle d = output::create_dataset(group, f.name, H5T_IEEE_F64LE, rows, cols, h5_path, gzip_level);
  output::write_string_attribute(d.get(), "units", stored_unit(f.unit), h5_path + ":" + path);
  const double* data = f.values.data();
  if (f.unit == "m" && unit.per_metre != 1.0) {  // lengths in the file's unit (a metre file: untouched)
    scaled_buffer.resize(f.values.size());  // no-op after the first step
    std::transform(f.values.begin(), f.values.end(), scaled_buffer.begin(), [&](double x) { return x * unit.per_metre; });
    data = scaled_buffer.data();
  }
  if (f.components == 6) {
    tensor_buffer.resize(static_cast<std::size_t>(entities) * 9);  // no-op after the first step
    for (long long e = 0; e < entities; ++e) {
      const double* v = data + 6 * e;  // data: the caller's values or their scaled copy
      double* t = tensor_buffer.data() + 9 * e;
      for (int k = 0; k < 9; ++k) t[k] = v[voigt_of_full[k]];
    }
    data = tensor_buffer.data();
  }
  if (parallel) {  // this rank's rows exchanged into its block, then written as one hyperslab
    const std::vector<unsigned char> block =
        (nodal ? *node_blocks : *element_blocks).gather(data, sizeof(double) * static_cast<std::size_t>(stored));
    output::write_selected_rows(d.get(), H5T_NATIVE_DOUBLE, block.data(), selection(nodal, cols), h5_path + ":" + path);
  } else
    output::write_rows(d.get(), H5T_NATIVE_DOUBLE, data, 0, rows, cols, h5_path + ":" + path);
}

void ResultsWriter::Impl::check_can_create(bool resume) {
  // Rank 0 makes the folder and probes the file; every rank learns the outcome (one error, the
  // same on every rank, instead of ranks waiting in a collective create).
  std::error_code ec;
  int status[2] = {1, 1};  // folder ok, file ok
  std::string reason;
  if (root) {
    std::filesystem::create_directories(directory, ec);
    status[0] = !ec && std::filesystem::is_directory(directory);
    if (!status[0]) reason = ec ? ec.message() : std::string("a file of that name exists");
    // fopen first: HDF5's own failure message is a multi-line stack without the errno text.
    // A resumed run appends to an existing file ("ab" creates none and truncates nothing).
    std::FILE* probe = status[0] ? std::fopen(h5_path.c_str(), resume ? "ab" : "wb") : nullptr;
    if (probe) std::fclose(probe);
    status[1] = probe != nullptr;
    if (status[0] && !status[1]) reason = std::strerror(errno);
  }
  if (parallel) {
    parallel::broadcast(status, 2, 0);
    parallel::broadcast(reason, 0);
  }
  if (!status[0])
    throw SetupError("cannot create output directory '" + directory + "': " + reason +
                     "; choose another output directory or fix its permissions");
  if (!status[1])
    throw SetupError("cannot create results file '" + h5_path + "': " + reason +
                     "; choose another output directory or fix its permissions");
}

namespace {

// Block index (line of block_names) of each element row a rank writes, -1 for none; a later block
// wins where blocks overlap (the XDMF then has one grid, grid_ranges).
std::vector<int> block_ids_of_rows(const std::vector<mesh::Block>& blocks,
                                   const std::vector<std::array<hsize_t, 2>>& element_runs, long long element_rows) {
  std::vector<int> id(static_cast<std::size_t>(element_rows), -1);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const long long first = blocks[b].first_element, end = first + blocks[b].element_count;
    long long packed = 0;
    for (const auto& r : element_runs) {
      const long long lo = std::max<long long>(first, static_cast<long long>(r[0]));
      const long long hi = std::min<long long>(end, static_cast<long long>(r[0] + r[1]));
      for (long long e = lo; e < hi; ++e) id[static_cast<std::size_t>(packed + e - static_cast<long long>(r[0]))] = static_cast<int>(b);
      packed += static_cast<long long>(r[1]);
    }
  }
  return id;
}

}  // namespace

void ResultsWriter::Impl::write_mesh(const MeshRows& rows, const std::vector<mesh::Block>& blocks,
                                     const ResultsOptions& options) {
  const std::string& p = h5_path;
  const long long n = nodes, e = elements;
  hid_t f = file.get();
  H5Handle g = output::create_group(f, "/mesh", p);
  output::create_group(f, "/steps", p);
  output::write_string_attribute(g.get(), "connectivity_order",
                                 "hex8 as VTK_HEXAHEDRON / docs/theory.md 2.1, 0-based node indices", p);
  // The unit of the coordinates and of every length field (readers: README "Units").
  output::write_string_attribute(f, "length_unit", unit.name, p);
  if (!options.run_id.empty()) output::write_string_attribute(f, "run_id", options.run_id, p);
  if (!options.mesh_sha256.empty()) output::write_string_attribute(f, "mesh_sha256", options.mesh_sha256, p);
  // Parallel: every rank's rows (all of them on rank 0 in the whole-mesh form, none elsewhere) are
  // exchanged into blocks of consecutive rows that each rank writes (collective; row_blocks.hpp).
  std::optional<output::RowBlocks> node_block, element_block;
  if (parallel) {
    node_block.emplace(rows.node_runs, n, output::chunk_rows(n, 3));
    element_block.emplace(rows.element_runs, e, output::chunk_rows(e, 9));
  }
  const auto write_mine = [&](hid_t d, hid_t type, const void* data, std::size_t value_bytes, bool nodal,
                              hsize_t rows_in_file, hsize_t cols, const std::string& what) {
    if (!parallel) return output::write_rows(d, type, data, 0, rows_in_file, cols, what);
    const output::RowBlocks& b = nodal ? *node_block : *element_block;
    const std::vector<unsigned char> block = b.gather(data, value_bytes * std::max<hsize_t>(cols, 1));
    output::write_selected_rows(d, type, block.data(), output::select_row_block(rows_in_file, cols, b.first(), b.count(), what),
                                what);
  };
  const int z = gzip_level;
  std::vector<double> xyz_in_unit(rows.coordinates, rows.coordinates + 3 * rows.node_rows);
  for (double& x : xyz_in_unit) x *= unit.per_metre;
  H5Handle xyz = output::create_dataset(g.get(), "coordinates", H5T_IEEE_F64LE, n, 3, p, z);
  output::write_string_attribute(xyz.get(), "units", unit.name, p);
  write_mine(xyz.get(), H5T_NATIVE_DOUBLE, xyz_in_unit.data(), sizeof(double), true, n, 3, p + ":/mesh/coordinates");
  H5Handle conn = output::create_dataset(g.get(), "connectivity", H5T_STD_I32LE, e, 8, p, z);
  output::write_string_attribute(conn.get(), "units", "1", p);  // node indices
  write_mine(conn.get(), H5T_NATIVE_INT, rows.connectivity, sizeof(int), false, e, 8, p + ":/mesh/connectivity");
  const std::vector<int> block_id = block_ids_of_rows(blocks, rows.element_runs, rows.element_rows);
  H5Handle bid = output::create_dataset(g.get(), "block_id", H5T_STD_I32LE, e, 0, p, z);
  output::write_string_attribute(bid.get(), "units", "1", p);  // block indices
  write_mine(bid.get(), H5T_NATIVE_INT, block_id.data(), sizeof(int), false, e, 0, p + ":/mesh/block_id");
  std::string joined;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (b > 0) joined += '\n';
    joined += blocks[b].name;
  }
  output::write_string_attribute(bid.get(), "block_names", joined, p);  // line b names block_id b
}

ResultsWriter::ResultsWriter(const std::string& directory, const mesh::Mesh& mesh, const ResultsSlab* slab,
                             std::optional<double> resume_time, const ResultsOptions& options) {
  if (mesh.coordinates.size() % 3 != 0 || mesh.connectivity.size() % 8 != 0)
    throw std::invalid_argument("ResultsWriter: mesh arrays are not [n][3] and [e][8]");
  // A parallel run: `mesh` is the whole mesh on rank 0 only; the others take its outline.
  const output::MeshOutline outline = output::outline_of(mesh, options.length_unit, slab != nullptr);
  MeshRows rows;
  if (!slab || parallel::is_root()) {  // the holder of the whole mesh writes all of it
    rows = {mesh.coordinates.data(), mesh.connectivity.data(), {}, {}, mesh.node_count(), mesh.element_count()};
    rows.node_runs.push_back({0, static_cast<hsize_t>(rows.node_rows)});
    rows.element_runs.push_back({0, static_cast<hsize_t>(rows.element_rows)});
  }
  open(directory, outline, slab, resume_time, options, rows);
}

ResultsWriter::ResultsWriter(const std::string& directory, const output::MeshOutline& outline, const ResultsSlab& slab,
                             const ResultsMeshRows& mesh_rows, std::optional<double> resume_time,
                             const ResultsOptions& options) {
  if (mesh_rows.coordinates.size() != 3 * static_cast<std::size_t>(slab.node_rows) ||
      mesh_rows.connectivity.size() != 8 * static_cast<std::size_t>(slab.element_rows))
    throw std::invalid_argument("ResultsWriter: the mesh rows are not the slab's [nodes][3] and [elements][8]");
  MeshRows rows{mesh_rows.coordinates.data(), mesh_rows.connectivity.data(), {}, {}, slab.node_rows, slab.element_rows};
  for (const auto& r : slab.node_runs) rows.node_runs.push_back({r[0], r[1]});
  for (const auto& r : slab.element_runs) rows.element_runs.push_back({r[0], r[1]});
  open(directory, outline, &slab, resume_time, options, rows);
}

void ResultsWriter::open(const std::string& directory, const output::MeshOutline& outline, const ResultsSlab* slab,
                         std::optional<double> resume_time, const ResultsOptions& options, const MeshRows& rows) {
  const long long e = outline.elements;
  for (const auto& b : outline.blocks)
    if (b.first_element < 0 || b.element_count < 0 || b.first_element + b.element_count > e)
      throw std::invalid_argument("ResultsWriter: block '" + b.name + "' runs past the last element");
  if (options.gzip_level < 0 || options.gzip_level > 9)
    throw std::invalid_argument("ResultsWriter: gzip level " + std::to_string(options.gzip_level) + " is not 0..9");
  impl_ = std::make_unique<Impl>(directory, outline.nodes, e, grid_ranges(outline.blocks, e), outline.unit,
                                 options.gzip_level);
  QuietHdf5Errors quiet;
  if (slab) {
    impl_->parallel = true;
    impl_->root = parallel::is_root();
    impl_->node_rows = slab->node_rows;
    impl_->element_rows = slab->element_rows;
    try {
      impl_->node_blocks.emplace(slab->node_runs, outline.nodes, output::chunk_rows(outline.nodes, 3));
      impl_->element_blocks.emplace(slab->element_runs, e, output::chunk_rows(e, 9));
      for (bool nodal : {true, false})
        for (hsize_t cols : {0, 3, 9}) impl_->selection(nodal, cols);  // the fields' shapes, before the loop
    } catch (const std::runtime_error& err) {
      throw SetupError(err.what());
    }
  }

  impl_->check_can_create(resume_time.has_value());
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (impl_->parallel) set_collective_buffer(fapl.get());
  if (resume_time && std::filesystem::file_size(impl_->h5_path) > 0 && impl_->open_for_resume(fapl.get(), *resume_time)) {
    const std::string file_run = output::read_string_attribute(impl_->file.get(), "run_id");
    if (!options.run_id.empty() && !file_run.empty() && file_run != options.run_id)
      throw SetupError("cannot continue '" + impl_->h5_path + "': it is the results file of run " + file_run +
                       ", not of run " + options.run_id + " that wrote the restart file; resume into another output folder (-o)");
    flush();
    return;
  }
  impl_->file = H5Handle(H5Fcreate(impl_->h5_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
  if (!impl_->file.valid())
    throw SetupError("cannot create results file '" + impl_->h5_path +
                     "': HDF5 H5Fcreate failed (is another run writing it? HDF5 locks open files)");

  try {
    impl_->write_mesh(rows, outline.blocks, options);
    flush();
  } catch (const std::runtime_error& err) {
    throw SetupError(err.what());
  }
}

ResultsWriter::~ResultsWriter() = default;  // H5Handle closes the file; the XDMF is already on disk

void ResultsWriter::write_step(double time, std::span<const FieldView> nodal,
                               std::span<const FieldView> element) {
  Impl& m = *impl_;
  if (!std::isfinite(time) || (m.doc.step_count() > 0 && !(time > m.last_time)))
    throw std::invalid_argument("ResultsWriter::write_step (" + m.h5_path + "): time " + std::to_string(time) +
                                " must be finite and larger than the previous step's " +
                                std::to_string(m.last_time));
  std::set<std::string> seen;
  m.check_fields(nodal, m.parallel ? m.node_rows : m.nodes, "nodal", m.nodal_spec, seen);
  m.check_fields(element, m.parallel ? m.element_rows : m.elements, "element", m.element_spec, seen);

  QuietHdf5Errors quiet;
  const std::string step = output::XdmfDocument::step_name(m.doc.step_count());
  const std::string base = "/steps/" + step;
  H5Handle g = output::create_group(m.file.get(), base, m.h5_path);
  output::write_double_attribute(g.get(), "time", time, m.h5_path + ":" + base);
  std::vector<output::XdmfAttribute> attributes;
  const struct {
    std::span<const FieldView> fields;
    const char* group;
    Center center;
    long long entities;
  } kinds[2] = {{nodal, "nodal", Center::node, m.nodes}, {element, "element", Center::cell, m.elements}};
  for (const auto& k : kinds) {
    // Creation order tracked: a resumed run lists the fields as they were written (open_for_resume).
    H5Handle sub = output::create_group(g.get(), k.group, m.h5_path, true);
    for (const auto& f : k.fields) {
      const std::string path = base + "/" + k.group + "/" + f.name;
      m.write_field(sub.get(), f, k.entities, path, k.center == Center::node);
      attributes.push_back({f.name, k.center, stored_components(f.components), path, m.stored_unit(f.unit)});
    }
  }
  if (m.doc.step_count() == 0) {
    for (const auto& f : nodal) m.nodal_spec.push_back({f.name, stored_components(f.components)});
    for (const auto& f : element) m.element_spec.push_back({f.name, stored_components(f.components)});
  }
  m.doc.add_step(time, attributes);
  m.last_time = time;
  flush();
}

void ResultsWriter::flush() {
  QuietHdf5Errors quiet;
  // HDF5 first: the XDMF must never name a dataset that is not on disk yet.
  if (H5Fflush(impl_->file.get(), H5F_SCOPE_LOCAL) < 0)
    throw output_failure(impl_->h5_path + " (H5Fflush)", errno);
  if (impl_->root) impl_->doc.write_atomically(impl_->xdmf_path);
}

int ResultsWriter::step_count() const { return impl_->doc.step_count(); }
const std::string& ResultsWriter::length_unit() const { return impl_->unit.name; }
const std::string& ResultsWriter::h5_path() const { return impl_->h5_path; }
const std::string& ResultsWriter::xdmf_path() const { return impl_->xdmf_path; }

}  // namespace tribex::solver
