// SPDX-License-Identifier: MIT
// Thin RAII and dataset helpers over the HDF5 C API, private to solver/output (hdf5.h stays out of
// public headers because tribex_core links HDF5 privately).
//
// Dataset creation and data writes are separate on purpose: in the parallel version (issue 6)
// every rank creates the same global datasets collectively and then writes its own slab of rows
// with write_rows(offset = first owned row), adding only a collective transfer property list.
#pragma once

#include <hdf5.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace tribex::solver::output {

/// Owns one HDF5 identifier and closes it with the matching H5?close.
class H5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Handle() = default;
  H5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  H5Handle(H5Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), closer_(o.closer_) {}
  H5Handle& operator=(H5Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, H5I_INVALID_HID);
      closer_ = o.closer_;
    }
    return *this;
  }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  ~H5Handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  void reset() {
    if (id_ >= 0 && closer_ != nullptr) closer_(id_);
    id_ = H5I_INVALID_HID;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

/// Silences HDF5's own error-stack printing for its lifetime (HDF5 prints its whole stack to stderr
/// on any failure; the caller reports one line itself), restoring the previous handler after.
class QuietHdf5Errors {
 public:
  QuietHdf5Errors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5Errors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietHdf5Errors(const QuietHdf5Errors&) = delete;
  QuietHdf5Errors& operator=(const QuietHdf5Errors&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

/// Creates group `name` under `loc`; throws std::runtime_error naming `file` on failure.
/// track_order: the group records the order its links are made in (H5_INDEX_CRT_ORDER), so that
/// a reader can list them in that order rather than by name.
H5Handle create_group(hid_t loc, const std::string& name, const std::string& file, bool track_order = false);

/// Creates a dataset of `rows` x `cols` (cols == 0: one-dimensional) elements of `file_type`,
/// never filled (every byte is written by write_rows). gzip_level 0: contiguous, allocated late;
/// 1..9: chunked (whole rows, about 512 KiB of values per chunk) with the shuffle filter and
/// deflate at that level (chunks are what parallel HDF5 compresses in a collective write).
H5Handle create_dataset(hid_t loc, const std::string& name, hid_t file_type, hsize_t rows,
                        hsize_t cols, const std::string& file, int gzip_level = 0);

/// Writes rows [row_offset, row_offset + rows) of a dataset created by create_dataset from a
/// contiguous [rows][cols] buffer of `mem_type`, through explicit file and memory dataspaces.
void write_rows(hid_t dataset, hid_t mem_type, const void* data, hsize_t row_offset, hsize_t rows,
                hsize_t cols, const std::string& what);

/// Rows per chunk of a compressed dataset of `rows` x `cols` (create_dataset): whole rows, about 64 Ki
/// values. A parallel writer that gives every rank whole chunks (BlockPlan) splits at these rows.
hsize_t chunk_rows(hsize_t rows, hsize_t cols);

/// A rank's block of consecutive rows [first, first + count) of a [rows][cols] dataset (cols 0:
/// one-dimensional) as the file and memory dataspaces of a collective write, with its transfer list.
/// One hyperslab of the same shape in file and memory: HDF5 maps it to chunks by the hyperslab's
/// bounds (the fast path), where a union of scattered runs is mapped element by element.
struct RowSelection {
  H5Handle file_space, mem_space, dxpl;
};
RowSelection select_row_block(hsize_t rows, hsize_t cols, hsize_t first, hsize_t count, const std::string& what);

/// Collective write of a block's rows (packed in `data`) through a RowSelection.
void write_selected_rows(hid_t dataset, hid_t mem_type, const void* data, const RowSelection& selection,
                         const std::string& what);

/// Writes a scalar double attribute `name` on `loc`.
void write_double_attribute(hid_t loc, const std::string& name, double value, const std::string& what);

/// Reads the string attribute `name` of `loc`; empty when it is missing or not a string.
std::string read_string_attribute(hid_t loc, const std::string& name);

/// Writes a fixed-length string attribute `name` on `loc`.
void write_string_attribute(hid_t loc, const std::string& name, const std::string& value,
                            const std::string& what);

}  // namespace tribex::solver::output
