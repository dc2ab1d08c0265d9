// SPDX-License-Identifier: MIT
// Restart files: HDF5, one group /rank_<r> per rank holding one 1-D dataset per archive entry
// (float64 for reals, int64 for integers), attribute `ranks` on the root. The ranks write in
// turn (token passing with barriers) with the serial driver: restart files are rare and small
// next to results.h5, and this keeps every rank's arrays in its own group.
#include <hdf5.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <system_error>

#include "solver/output/h5_handles.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {
namespace {

using output::H5Handle;

// Bumped when the archive layout changes; a file of another version is refused (exit 2).
constexpr double kRestartFormatVersion = 1;

void write_group(hid_t file, const StateArchive& a, const std::string& path) {
  H5Handle group = output::create_group(file, "rank_" + std::to_string(parallel::rank()), path);
  for (const auto& [name, values] : a.reals) {
    H5Handle d = output::create_dataset(group.get(), name, H5T_IEEE_F64LE, values.size(), 0, path);
    output::write_rows(d.get(), H5T_NATIVE_DOUBLE, values.data(), 0, values.size(), 0, path + ":" + name);
  }
  for (const auto& [name, values] : a.integers) {
    H5Handle d = output::create_dataset(group.get(), name, H5T_STD_I64LE, values.size(), 0, path);
    output::write_rows(d.get(), H5T_NATIVE_LLONG, values.data(), 0, values.size(), 0, path + ":" + name);
  }
}

struct ReadContext {
  StateArchive* archive = nullptr;
  std::string path;
  std::uintmax_t file_bytes = 0;  // sizes read from the file are checked against it before allocating
  bool failed = false;
  std::string refused;  // a dataset whose size the file cannot hold (issue 54, item 11)
  const std::function<bool(const std::string&)>* wanted = nullptr;  // null: every dataset
};

herr_t read_member(hid_t group, const char* name, const H5L_info_t*, void* data) {
  auto* ctx = static_cast<ReadContext*>(data);
  if (ctx->wanted && *ctx->wanted && !(*ctx->wanted)(name)) return 0;
  H5Handle d(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  H5Handle space(d.valid() ? H5Dget_space(d.get()) : H5I_INVALID_HID, H5Sclose);
  H5Handle type(d.valid() ? H5Dget_type(d.get()) : H5I_INVALID_HID, H5Tclose);
  if (!space.valid() || !type.valid()) {
    ctx->failed = true;
    return -1;
  }
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  // tribex writes restart datasets uncompressed and contiguous (write_group): 8 bytes per value
  // stored in the file. A larger stated size is an edited or damaged file, refused before allocating.
  if (n < 0 || static_cast<std::uintmax_t>(n) > ctx->file_bytes / 8) {
    char gb[32];
    std::snprintf(gb, sizeof gb, "%.3g", 8.0 * static_cast<double>(n) / 1e9);
    ctx->refused = ctx->path + ": error: restart dataset '" + name + "' states " + std::to_string(n) +
                   " values (" + gb + " GB), more than the file's " +
                   std::to_string(ctx->file_bytes) + " bytes can hold (an edited or damaged restart file?); restart "
                   "from a file a tribex run wrote";
    return -1;
  }
  herr_t status = 0;
  if (H5Tget_class(type.get()) == H5T_FLOAT) {
    auto& v = ctx->archive->reals[name];
    v.resize(static_cast<std::size_t>(n));
    if (n > 0) status = H5Dread(d.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  } else {
    auto& v = ctx->archive->integers[name];
    v.resize(static_cast<std::size_t>(n));
    if (n > 0) status = H5Dread(d.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  }
  if (status < 0) ctx->failed = true;
  return status < 0 ? -1 : 0;
}

// libhdf5 (1.10, Debian 12) iterates a damaged symbol-table group without end, growing its memory
// (the restart fuzz target's finding: 24 GB in 65 s from a 97 kB file). While a restart file is read
// the address space may grow by at most 256 MB + 8 x the file's size (a tribex restart file is read
// with a few times its size); beyond it HDF5's allocations fail and the file is reported as damaged.
// A lower limit of the user's (ulimit -v) is kept. Restored on scope exit.
class AddressSpaceBudget {
 public:
  explicit AddressSpaceBudget(std::uintmax_t file_bytes) {
    if (getrlimit(RLIMIT_AS, &saved_) != 0) return;
    long pages = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
      std::fclose(f);
    }
    if (pages <= 0) return;
    const double now = static_cast<double>(pages) * static_cast<double>(sysconf(_SC_PAGESIZE));
    const double budget = now + 256e6 + 8.0 * static_cast<double>(file_bytes);
    if (saved_.rlim_cur != RLIM_INFINITY && static_cast<double>(saved_.rlim_cur) <= budget) return;
    rlimit bounded = saved_;
    bounded.rlim_cur = static_cast<rlim_t>(budget);
    budget_ = bounded.rlim_cur;
    active_ = setrlimit(RLIMIT_AS, &bounded) == 0;
  }
  /// The address space is within 10 % of the budget (an allocation failed for it, not another fault).
  bool exhausted() const {
    long pages = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(f, "%ld", &pages) != 1) pages = 0;
      std::fclose(f);
    }
    const double now = static_cast<double>(pages) * static_cast<double>(sysconf(_SC_PAGESIZE));
    return active_ && now > 0.9 * static_cast<double>(budget_);
  }
  ~AddressSpaceBudget() {
    if (active_) setrlimit(RLIMIT_AS, &saved_);
  }
  AddressSpaceBudget(const AddressSpaceBudget&) = delete;
  AddressSpaceBudget& operator=(const AddressSpaceBudget&) = delete;
  bool active() const { return active_; }

 private:
  rlimit saved_{};
  rlim_t budget_ = 0;
  bool active_ = false;
};

}  // namespace

void write_restart_file(const std::string& path, const StateArchive& archive, const std::string& run_id) {
  output::QuietHdf5Errors quiet;
  const std::string part = path + ".part";
  int failed = 0;
  for (int r = 0; r < parallel::size(); ++r) {
    if (r == parallel::rank()) {
      try {
        H5Handle file(r == 0 ? H5Fcreate(part.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT)
                             : H5Fopen(part.c_str(), H5F_ACC_RDWR, H5P_DEFAULT),
                      H5Fclose);
        if (!file.valid()) throw std::runtime_error("cannot open " + part);
        if (r == 0) {
          output::write_double_attribute(file.get(), "ranks", parallel::size(), part);
          output::write_double_attribute(file.get(), "format_version", kRestartFormatVersion, part);
          if (!run_id.empty()) output::write_string_attribute(file.get(), "run_id", run_id, part);
        }
        write_group(file.get(), archive, part);
      } catch (const std::exception&) {
        failed = 1;
      }
    }
    parallel::barrier();
  }
  double any = failed;
  parallel::sum(&any, 1);
  if (any > 0) throw NumericalFailure("could not write the restart file " + path + " (disk full?)");
  if (parallel::is_root()) {
    std::error_code ec;
    std::filesystem::rename(part, path, ec);
    if (ec) failed = 1;
  }
  parallel::barrier();
}

RestartFile::RestartFile(const std::string& path) : path_(path) {
  output::QuietHdf5Errors quiet;
  if (!std::filesystem::is_regular_file(path))
    throw SetupError(path + ": error: no such restart file; give a restart_<k>.h5 or restart.h5 written by a run with "
                            "'begin restart output'");
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) throw SetupError(path + ": error: not a readable HDF5 restart file");
  try {
    double ranks = 0;
    {
      H5Handle a(H5Aopen(file_, "ranks", H5P_DEFAULT), H5Aclose);
      if (!a.valid() || H5Aread(a.get(), H5T_NATIVE_DOUBLE, &ranks) < 0)
        throw SetupError(path + ": error: not a tribex restart file (no 'ranks' attribute)");
    }
    double version = 0;
    {
      H5Handle a(H5Aopen(file_, "format_version", H5P_DEFAULT), H5Aclose);
      if (!a.valid() || H5Aread(a.get(), H5T_NATIVE_DOUBLE, &version) < 0 || version != kRestartFormatVersion)
        throw SetupError(path + ": error: restart file format version " + std::to_string(static_cast<int>(version)) +
                         ", this tribex reads version " + std::to_string(static_cast<int>(kRestartFormatVersion)) +
                         "; restart with the tribex that wrote it");
    }
    if (!(ranks >= 1 && ranks <= 1e7))
      throw SetupError(path + ": error: restart file states " + std::to_string(ranks) +
                       " ranks (an edited or damaged restart file?); restart from a file a tribex run wrote");
    ranks_ = static_cast<int>(ranks);
  } catch (...) {
    H5Fclose(file_);
    throw;
  }
  std::error_code size_error;
  file_bytes_ = std::filesystem::file_size(path, size_error);
}

RestartFile::~RestartFile() {
  output::QuietHdf5Errors quiet;
  if (file_ >= 0) H5Fclose(file_);
}

StateArchive RestartFile::read_group(int g, const std::function<bool(const std::string&)>& wanted) const {
  output::QuietHdf5Errors quiet;
  StateArchive archive;
  const std::string group_name = "rank_" + std::to_string(g);
  H5Handle group(H5Gopen2(file_, group_name.c_str(), H5P_DEFAULT), H5Gclose);
  if (!group.valid()) throw SetupError(path_ + ": error: restart file has no group " + group_name);
  ReadContext ctx;
  ctx.archive = &archive;
  ctx.path = path_;
  ctx.file_bytes = file_bytes_;
  ctx.wanted = &wanted;
  herr_t walked = 0;
  bool exhausted = false;
  {
    const AddressSpaceBudget budget(ctx.file_bytes);
    try {
      walked = H5Literate(group.get(), H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, read_member, &ctx);
    } catch (const std::bad_alloc&) {
      exhausted = true;
    }
    exhausted = exhausted || (walked < 0 && ctx.refused.empty() && budget.exhausted());
  }
  if (exhausted)
    throw SetupError(path_ + ": error: restart file is damaged: reading " + group_name + " took more than 256 MB + 8 x the "
                     "file's size of memory (a damaged HDF5 group); restart from a file a tribex run wrote");
  if (!ctx.refused.empty()) throw SetupError(ctx.refused);
  if (walked < 0 || ctx.failed)
    throw SetupError(path_ + ": error: restart file is damaged (a dataset of " + group_name + " cannot be read)");
  return archive;
}

StateArchive read_restart_file(const std::string& path) {
  const RestartFile file(path);
  if (file.ranks() != parallel::size())
    throw SetupError(path + ": error: the restart file was written by " + std::to_string(file.ranks()) +
                     " rank(s), this run has " + std::to_string(parallel::size()) + "; restart with mpirun -np " +
                     std::to_string(file.ranks()));
  return file.read_group(parallel::rank());
}

}  // namespace tribex::solver
