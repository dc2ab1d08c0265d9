// SPDX-License-Identifier: MIT
// Restart files, format version 2 (2026-11-29): HDF5 with attributes `ranks`, `format_version`, `run_id`
// on the root and, per archive entry NAME, dataset reals/NAME (float64) or integers/NAME (int64) holding
// every rank's array one after the other in rank order, with real_counts/NAME or integer_counts/NAME
// (int64 [ranks]) giving each rank's value count, -1 where that rank has no such entry. Rank g's array
// starts at the sum of the counts (>= 0) before it. Written in one go with parallel HDF5 (mpio driver,
// as results.h5): one allgather tells every rank every rank's entry names and sizes, all ranks create
// the same datasets (collective metadata: O(entries), not O(ranks x entries)), rank 0 writes the counts
// and each rank writes its own slice of every entry. Why this layout: solver/README.md "Restart".
// Version 1 (one group rank_<r> per rank, one dataset per entry, written rank after rank) is still read.
#include <hdf5.h>
#include <mpi.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>
#include <system_error>
#include <vector>

#include "solver/output/h5_handles.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/restart/state_archive.hpp"

namespace tribex::solver {
namespace {

using output::H5Handle;

// Bumped when the archive layout changes; a file of another version is refused (exit 2).
constexpr double kRestartFormatVersion = 2;
constexpr double kFirstFormatVersion = 1;  // rank_<r> groups: still read (a user's file from before)

// One archive entry as every rank learns it before the collective creation of the datasets.
struct EntryShape {
  std::string name;
  bool integer = false;
  std::uint64_t count = 0;
};

// This rank's entries, reals then integers, each in name order (the order of a group's datasets since the first format):
// per entry a type byte, the value count, the name's length and the name.
std::vector<char> encode_shapes(const StateArchive& a) {
  std::vector<char> out;
  const auto put = [&out](const void* p, std::size_t n) { out.insert(out.end(), static_cast<const char*>(p), static_cast<const char*>(p) + n); };
  const auto entry = [&](const std::string& name, char integer, std::uint64_t count) {
    const std::uint64_t length = name.size();
    put(&integer, 1);
    put(&count, sizeof count);
    put(&length, sizeof length);
    put(name.data(), name.size());
  };
  for (const auto& [name, values] : a.reals) entry(name, 0, values.size());
  for (const auto& [name, values] : a.integers) entry(name, 1, values.size());
  return out;
}

std::vector<EntryShape> decode_shapes(const char* p, const char* end) {
  std::vector<EntryShape> shapes;
  while (p < end) {
    EntryShape e;
    std::uint64_t length = 0;
    e.integer = *p++ != 0;
    std::memcpy(&e.count, p, sizeof e.count);
    p += sizeof e.count;
    std::memcpy(&length, p, sizeof length);
    p += sizeof length;
    e.name.assign(p, static_cast<std::size_t>(length));
    p += length;
    shapes.push_back(std::move(e));
  }
  return shapes;
}

// [rank][entry]: every rank's entry names, types and sizes, on every rank (an allgather of the byte
// counts, then of the bytes). One rank: its own, no MPI call (unit tests run without MPI_Init).
std::vector<std::vector<EntryShape>> gather_shapes(const StateArchive& a) {
  const std::vector<char> mine = encode_shapes(a);
  std::vector<int> offsets;
  const std::string all = parallel::all_gather(std::string(mine.begin(), mine.end()), offsets);
  std::vector<std::vector<EntryShape>> shapes;
  for (std::size_t r = 0; r + 1 < offsets.size(); ++r)
    shapes.push_back(decode_shapes(all.data() + offsets[r], all.data() + offsets[r + 1]));
  return shapes;
}

// [entry name] -> every rank's value count, -1 where the rank has no such entry: the counts datasets.
using Counts = std::map<std::string, std::vector<long long>>;
void count_entries(const std::vector<std::vector<EntryShape>>& shapes, Counts& reals, Counts& integers) {
  const std::size_t ranks = shapes.size();
  for (std::size_t r = 0; r < ranks; ++r)
    for (const EntryShape& e : shapes[r]) {
      auto& c = (e.integer ? integers : reals)[e.name];
      if (c.empty()) c.assign(ranks, -1);
      c[r] = static_cast<long long>(e.count);
    }
}

// One kind (reals or integers): first every rank creates the same datasets (parallel HDF5 requires every
// metadata change of every rank, in the same order; about 100 objects stay in HDF5's metadata cache, no
// I/O until the close), then rank 0 writes the counts and each rank its own slice of the values
// (independent writes into contiguous datasets the mpio driver allocates at creation). A failed write (a
// full disk) is returned, not thrown: a rank that left here early would skip creations the others still
// make, and the collective close would then wait for it for ever.
template <class Map>
bool write_kind(hid_t file, const char* kind, const char* counts_kind, const Counts& counts, const Map& mine,
                hid_t file_type, hid_t mem_type, const std::string& path) {
  const std::size_t me = static_cast<std::size_t>(parallel::rank());
  H5Handle values_group = output::create_group(file, kind, path), counts_group = output::create_group(file, counts_kind, path);
  std::vector<H5Handle> values, sizes;
  for (const auto& [name, c] : counts) {
    long long total = 0;
    for (long long n : c) total += std::max(n, 0LL);
    values.push_back(output::create_dataset(values_group.get(), name, file_type, static_cast<hsize_t>(total), 0, path));
    sizes.push_back(output::create_dataset(counts_group.get(), name, H5T_STD_I64LE, c.size(), 0, path));
  }
  bool ok = true;
  std::size_t k = 0;
  for (const auto& [name, c] : counts) {
    long long offset = 0;
    for (std::size_t r = 0; r < me; ++r) offset += std::max(c[r], 0LL);
    const auto it = mine.find(name);
    try {
      if (me == 0) output::write_rows(sizes[k].get(), H5T_NATIVE_LLONG, c.data(), 0, c.size(), 0, path);
      if (it != mine.end() && !it->second.empty())  // an empty slice selects nothing
        output::write_rows(values[k].get(), mem_type, it->second.data(), static_cast<hsize_t>(offset), it->second.size(), 0,
                           path + ":" + kind + "/" + name);
    } catch (const std::runtime_error&) {
      ok = false;
    }
    ++k;
  }
  return ok;
}

// Both kinds; throws (after every collective creation) when a write of this rank failed.
void write_entries(hid_t file, const std::vector<std::vector<EntryShape>>& shapes, const StateArchive& a,
                   const std::string& path) {
  Counts reals, integers;
  count_entries(shapes, reals, integers);
  const bool reals_written = write_kind(file, "reals", "real_counts", reals, a.reals, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, path);
  const bool integers_written =
      write_kind(file, "integers", "integer_counts", integers, a.integers, H5T_STD_I64LE, H5T_NATIVE_LLONG, path);
  if (!reals_written || !integers_written) throw std::runtime_error("could not write " + path);
}

struct ReadContext {
  StateArchive* archive = nullptr;
  std::string path;
  std::uintmax_t file_bytes = 0;  // sizes read from the file are checked against it before allocating
  bool failed = false;
  std::string refused;  // a dataset whose size the file cannot hold (issue 54, item 11)
  const std::function<bool(const std::string&)>* wanted = nullptr;  // null: every dataset
  // Version 2: the counts group beside the values group walked, the rank read and the file's rank count.
  hid_t counts_group = H5I_INVALID_HID;
  int rank = 0, ranks = 1;
};

// The value count of dataset `name` (`d`, opened), or -1 after recording why it cannot be read.
hssize_t checked_size(hid_t d, const char* name, ReadContext* ctx) {
  H5Handle space(d >= 0 ? H5Dget_space(d) : H5I_INVALID_HID, H5Sclose);
  if (!space.valid()) {
    ctx->failed = true;
    return -1;
  }
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  // tribex writes restart datasets uncompressed and contiguous (write_kind): 8 bytes per value
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
  return n;
}

// Values [offset, offset + count) of dataset `d` into the archive, as reals or integers by the dataset's
// type class (an edited file's integer-typed `u` then reaches the archive's check: state_archive.hpp).
herr_t read_values(hid_t d, const char* name, hsize_t offset, hsize_t count, ReadContext* ctx) {
  H5Handle type(H5Dget_type(d), H5Tclose);
  if (!type.valid()) {
    ctx->failed = true;
    return -1;
  }
  const bool real = H5Tget_class(type.get()) == H5T_FLOAT;
  void* data = nullptr;
  if (real) {
    auto& v = ctx->archive->reals[name];
    v.resize(static_cast<std::size_t>(count));
    data = v.data();
  } else {
    auto& v = ctx->archive->integers[name];
    v.resize(static_cast<std::size_t>(count));
    data = v.data();
  }
  if (count == 0) return 0;  // nothing to select (an empty slice may start at the dataset's end)
  H5Handle file_space(H5Dget_space(d), H5Sclose);
  H5Handle mem_space(H5Screate_simple(1, &count, nullptr), H5Sclose);
  if (!file_space.valid() || !mem_space.valid() ||
      H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &offset, nullptr, &count, nullptr) < 0) {
    ctx->failed = true;
    return -1;
  }
  const herr_t status = H5Dread(d, real ? H5T_NATIVE_DOUBLE : H5T_NATIVE_LLONG, mem_space.get(), file_space.get(),
                                H5P_DEFAULT, data);
  if (status < 0) ctx->failed = true;
  return status < 0 ? -1 : 0;
}

// Version 1: dataset `name` of group rank_<g>, whole.
herr_t read_member(hid_t group, const char* name, const H5L_info_t*, void* data) {
  auto* ctx = static_cast<ReadContext*>(data);
  if (ctx->wanted && *ctx->wanted && !(*ctx->wanted)(name)) return 0;
  H5Handle d(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  const hssize_t n = checked_size(d.get(), name, ctx);
  if (n < 0) return -1;
  return read_values(d.get(), name, 0, static_cast<hsize_t>(n), ctx);
}

// Version 2: rank ctx->rank's slice of dataset `name` (all ranks' arrays in rank order), placed by the
// counts dataset of the same name; a count of -1: the rank has no such entry.
herr_t read_slice(hid_t group, const char* name, const H5L_info_t*, void* data) {
  auto* ctx = static_cast<ReadContext*>(data);
  if (ctx->wanted && *ctx->wanted && !(*ctx->wanted)(name)) return 0;
  H5Handle d(H5Dopen2(group, name, H5P_DEFAULT), H5Dclose);
  H5Handle c(H5Dopen2(ctx->counts_group, name, H5P_DEFAULT), H5Dclose);
  const hssize_t n = checked_size(d.get(), name, ctx);
  const hssize_t ranks = n < 0 ? -1 : checked_size(c.get(), name, ctx);
  if (n < 0 || ranks < 0) return -1;
  std::vector<long long> counts(static_cast<std::size_t>(ranks));
  if (ranks != ctx->ranks || H5Dread(c.get(), H5T_NATIVE_LLONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, counts.data()) < 0) {
    ctx->failed = true;
    return -1;
  }
  long long offset = 0, total = 0;
  bool valid = true;
  for (int r = 0; r < ctx->ranks; ++r) {
    valid = valid && counts[r] >= -1 && counts[r] <= n;
    if (r == ctx->rank) offset = total;
    total += valid ? std::max(counts[r], 0LL) : 0;
  }
  if (!valid || total != n) {
    ctx->refused = ctx->path + ": error: restart dataset '" + name + "' holds " + std::to_string(n) +
                   " values, its per-rank counts do not add up to that (an edited or damaged restart file?); restart "
                   "from a file a tribex run wrote";
    return -1;
  }
  if (counts[ctx->rank] < 0) return 0;
  return read_values(d.get(), name, static_cast<hsize_t>(offset), static_cast<hsize_t>(counts[ctx->rank]), ctx);
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

// The file's `format_version` attribute, 0 when it has none.
double format_version_of(hid_t file) {
  double version = 0;
  H5Handle a(H5Aopen(file, "format_version", H5P_DEFAULT), H5Aclose);
  if (!a.valid() || H5Aread(a.get(), H5T_NATIVE_DOUBLE, &version) < 0) return 0;
  return version;
}

// Is there room for the file in `part`'s folder? Its values (8 bytes each) plus 1 KiB of metadata per
// object and 64 KiB. Checked by rank 0 before the file is made, for every rank (one broadcast): parallel
// HDF5 cannot close a file whose metadata it could not write, and its exit handler then crashes on the
// half-closed file (tried: a 250 KiB tmpfs, SIGSEGV in H5F__close_cb at MPI_Finalize after exit 3's
// message). A disk that fills between the check and the write can still end so.
bool room_for(const std::string& part, const std::vector<std::vector<EntryShape>>& shapes) {
  int room = 1;
  if (parallel::is_root()) {
    std::error_code ec;
    std::filesystem::remove(part, ec);  // an earlier failed write's leftover
    double bytes = 65536;
    for (const auto& rank : shapes)
      for (const EntryShape& e : rank) bytes += 8.0 * static_cast<double>(e.count) + 2048;  // values and counts datasets
    const auto space = std::filesystem::space(std::filesystem::path(part).parent_path().empty()
                                                  ? std::filesystem::path(".")
                                                  : std::filesystem::path(part).parent_path(),
                                              ec);
    room = ec || static_cast<double>(space.available) >= bytes ? 1 : 0;
  }
  if (parallel::size() > 1) parallel::broadcast(&room, 1, 0);
  return room != 0;
}

}  // namespace

void write_restart_file(const std::string& path, const StateArchive& archive, const std::string& run_id) {
  output::QuietHdf5Errors quiet;
  const std::string part = path + ".part";
  const std::vector<std::vector<EntryShape>> shapes = gather_shapes(archive);
  if (!room_for(part, shapes)) throw NumericalFailure("could not write the restart file " + path + " (disk full?)");
  int failed = 0;
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!fapl.valid() || (parallel::size() > 1 && H5Pset_fapl_mpio(fapl.get(), MPI_COMM_WORLD, MPI_INFO_NULL) < 0)) failed = 1;
  // Collective in a parallel run: every rank opens, creates and closes; a rank whose write failed
  // (disk full) goes on to the close so that no rank waits for it, and the failure is agreed after.
  const hid_t file = failed ? H5I_INVALID_HID : H5Fcreate(part.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get());
  if (file < 0) {
    failed = 1;
  } else {
    try {
      // Attributes are metadata too: every rank writes the same values.
      output::write_double_attribute(file, "ranks", parallel::size(), part);
      output::write_double_attribute(file, "format_version", kRestartFormatVersion, part);
      if (!run_id.empty()) output::write_string_attribute(file, "run_id", run_id, part);
      write_entries(file, shapes, archive, part);
    } catch (const std::exception&) {
      failed = 1;
    }
    if (H5Fclose(file) < 0) failed = 1;  // the metadata is written here: a full disk may show only now
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
    const double version = format_version_of(file_);
    if (version != kRestartFormatVersion && version != kFirstFormatVersion)
      throw SetupError(path + ": error: restart file format version " + std::to_string(static_cast<int>(version)) +
                       ", this tribex reads versions " + std::to_string(static_cast<int>(kFirstFormatVersion)) + " and " +
                       std::to_string(static_cast<int>(kRestartFormatVersion)) + "; restart with the tribex that wrote it");
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
  const bool first_format = format_version_of(file_) == kFirstFormatVersion;
  // Version 1: group rank_<g>, whole. Version 2: rank g's slice of every entry, reals then integers.
  const std::string group_name = first_format ? "rank_" + std::to_string(g) : "rank " + std::to_string(g) + "'s arrays";
  std::vector<std::array<H5Handle, 2>> walks;  // {values group, counts group}
  for (const auto& [values, counts] : first_format ? std::vector<std::array<std::string, 2>>{{group_name, ""}}
                                                   : std::vector<std::array<std::string, 2>>{{"reals", "real_counts"},
                                                                                           {"integers", "integer_counts"}}) {
    walks.push_back({H5Handle(H5Gopen2(file_, values.c_str(), H5P_DEFAULT), H5Gclose),
                     H5Handle(counts.empty() ? H5I_INVALID_HID : H5Gopen2(file_, counts.c_str(), H5P_DEFAULT), H5Gclose)});
    if (!walks.back()[0].valid() || (!counts.empty() && !walks.back()[1].valid()) || g < 0 || g >= ranks_)
      throw SetupError(path_ + ": error: restart file has no group " + (first_format ? group_name : values + " or " + counts) +
                       (first_format || (g >= 0 && g < ranks_) ? "" : " for rank " + std::to_string(g)));
  }
  ReadContext ctx;
  ctx.archive = &archive;
  ctx.path = path_;
  ctx.file_bytes = file_bytes_;
  ctx.wanted = &wanted;
  ctx.rank = g;
  ctx.ranks = ranks_;
  herr_t walked = 0;
  bool exhausted = false;
  {
    const AddressSpaceBudget budget(ctx.file_bytes);
    try {
      for (const auto& w : walks) {
        ctx.counts_group = w[1].get();
        if (walked >= 0)
          walked = H5Literate(w[0].get(), H5_INDEX_NAME, H5_ITER_NATIVE, nullptr, first_format ? read_member : read_slice, &ctx);
      }
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
