// SPDX-License-Identifier: MIT
#include "solver/output/h5_handles.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "solver/errors.hpp"

namespace tribex::solver::output {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& action) {
  const int error_number = errno;
  throw output_failure(what + " (HDF5 could not " + action + ")", error_number);
}

}  // namespace

H5Handle create_group(hid_t loc, const std::string& name, const std::string& file, bool track_order) {
  H5Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose);
  if (!gcpl.valid() ||
      (track_order && H5Pset_link_creation_order(gcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED) < 0))
    fail(file, "prepare group '" + name + "'");
  H5Handle g(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT), H5Gclose);
  if (!g.valid()) fail(file, "create group '" + name + "'");
  return g;
}

H5Handle create_dataset(hid_t loc, const std::string& name, hid_t file_type, hsize_t rows,
                        hsize_t cols, const std::string& file, int gzip_level) {
  const hsize_t dims[2] = {rows, cols};
  const int rank = cols == 0 ? 1 : 2;
  H5Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  H5Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  // No fill pass: the whole dataset is written right after creation, so filling would double
  // the I/O of every step for nothing.
  if (!space.valid() || !dcpl.valid() || H5Pset_fill_time(dcpl.get(), H5D_FILL_TIME_NEVER) < 0)
    fail(file, "prepare dataset '" + name + "'");
  if (gzip_level > 0 && rows > 0) {
    // Whole rows per chunk, 64 Ki values (512 KiB of f64): under HDF5's default 1 MiB chunk cache,
    // large enough for deflate to find the repeats. Shuffle groups the bytes of equal significance
    // (the exponents of neighbouring values agree), which is what makes float64 compress at all.
    const hsize_t chunk[2] = {chunk_rows(rows, cols), cols};
    if (H5Pset_chunk(dcpl.get(), rank, chunk) < 0 || H5Pset_shuffle(dcpl.get()) < 0 ||
        H5Pset_deflate(dcpl.get(), static_cast<unsigned>(gzip_level)) < 0)
      fail(file, "prepare compressed dataset '" + name + "'");
  } else if (H5Pset_alloc_time(dcpl.get(), H5D_ALLOC_TIME_LATE) < 0) {
    fail(file, "prepare dataset '" + name + "'");
  }
  // No chunk cache: every chunk is written whole by one H5Dwrite, so caching gains nothing, and a
  // chunk left dirty in the cache when the disk is full makes H5Fclose fail and HDF5's exit
  // handler crash on the half-closed file (cli_disk_full: SIGSEGV); uncached, the write fails.
  H5Handle dapl(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose);
  if (!dapl.valid() || H5Pset_chunk_cache(dapl.get(), 0, 0, H5D_CHUNK_CACHE_W0_DEFAULT) < 0)
    fail(file, "prepare dataset '" + name + "'");
  H5Handle d(H5Dcreate2(loc, name.c_str(), file_type, space.get(), H5P_DEFAULT, dcpl.get(), dapl.get()),
             H5Dclose);
  if (!d.valid()) fail(file, "create dataset '" + name + "'");
  return d;
}

void write_rows(hid_t dataset, hid_t mem_type, const void* data, hsize_t row_offset, hsize_t rows,
                hsize_t cols, const std::string& what) {
  const int rank = cols == 0 ? 1 : 2;
  const hsize_t count[2] = {rows, std::max<hsize_t>(cols, 1)};
  const hsize_t start[2] = {row_offset, 0};
  H5Handle file_space(H5Dget_space(dataset), H5Sclose);
  H5Handle mem_space(H5Screate_simple(rank, count, nullptr), H5Sclose);
  if (!file_space.valid() || !mem_space.valid() ||
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr) < 0)
    fail(what, "select rows");
  if (rows == 0) return;  // an empty slab (a rank owning nothing) writes nothing
  if (H5Dwrite(dataset, mem_type, mem_space.get(), file_space.get(), H5P_DEFAULT, data) < 0)
    fail(what, "write");
}

hsize_t chunk_rows(hsize_t rows, hsize_t cols) {
  return std::clamp<hsize_t>(65536 / std::max<hsize_t>(cols, 1), 1, std::max<hsize_t>(rows, 1));
}

RowSelection select_row_block(hsize_t rows, hsize_t cols, hsize_t first, hsize_t count, const std::string& what) {
  const hsize_t width = std::max<hsize_t>(cols, 1);
  const int rank = cols == 0 ? 1 : 2;
  const hsize_t file_dims[2] = {rows, width}, mem_dims[2] = {std::max<hsize_t>(count, 1), width};
  RowSelection s{H5Handle(H5Screate_simple(rank, file_dims, nullptr), H5Sclose),
                 H5Handle(H5Screate_simple(rank, mem_dims, nullptr), H5Sclose),
                 H5Handle(H5Pcreate(H5P_DATASET_XFER), H5Pclose)};
  if (!s.file_space.valid() || !s.mem_space.valid() || !s.dxpl.valid() ||
      H5Pset_dxpl_mpio(s.dxpl.get(), H5FD_MPIO_COLLECTIVE) < 0)
    fail(what, "prepare a collective write");
  const hsize_t start[2] = {first, 0}, block[2] = {count, width};
  // An empty block selects nothing (HDF5 refuses a zero count) but the rank still takes part.
  if (count == 0 ? (H5Sselect_none(s.file_space.get()) < 0 || H5Sselect_none(s.mem_space.get()) < 0)
                 : H5Sselect_hyperslab(s.file_space.get(), H5S_SELECT_SET, start, nullptr, block, nullptr) < 0)
    fail(what, "select rows");
  return s;
}

void write_selected_rows(hid_t dataset, hid_t mem_type, const void* data, const RowSelection& selection,
                         const std::string& what) {
  static const double nothing[9] = {};  // HDF5 wants a buffer even when this rank writes no rows
  if (H5Dwrite(dataset, mem_type, selection.mem_space.get(), selection.file_space.get(), selection.dxpl.get(),
               data ? data : nothing) < 0)
    fail(what, "write");
}

void write_double_attribute(hid_t loc, const std::string& name, double value, const std::string& what) {
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Handle a(H5Acreate2(loc, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT),
             H5Aclose);
  if (!a.valid() || H5Awrite(a.get(), H5T_NATIVE_DOUBLE, &value) < 0)
    fail(what, "write attribute '" + name + "'");
}

std::string read_string_attribute(hid_t loc, const std::string& name) {
  if (H5Aexists(loc, name.c_str()) <= 0) return {};
  H5Handle a(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose);
  H5Handle type(a.valid() ? H5Aget_type(a.get()) : H5I_INVALID_HID, H5Tclose);
  if (!type.valid() || H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0) return {};
  std::string value(H5Tget_size(type.get()), '\0');
  if (H5Aread(a.get(), type.get(), value.data()) < 0) return {};
  value.resize(std::strlen(value.c_str()));  // fixed-length strings carry their NUL
  return value;
}

void write_string_attribute(hid_t loc, const std::string& name, const std::string& value,
                            const std::string& what) {
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  // Size includes the terminating NUL (H5T_STR_NULLTERM), so readers see the whole text.
  if (!type.valid() || H5Tset_size(type.get(), value.size() + 1) < 0)
    fail(what, "make string type for '" + name + "'");
  H5Handle a(H5Acreate2(loc, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (!a.valid() || H5Awrite(a.get(), type.get(), value.c_str()) < 0)
    fail(what, "write attribute '" + name + "'");
}

}  // namespace tribex::solver::output
