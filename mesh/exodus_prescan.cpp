// SPDX-License-Identifier: MIT
// prescan_netcdf_classic (exodus_prescan.hpp). The layout (big-endian):
//   header   = magic numrecs dim_list gatt_list var_list
//   dim_list = ABSENT | NC_DIMENSION nelems {name length}
//   att_list = ABSENT | NC_ATTRIBUTE nelems {name nc_type nelems values (padded to 4)}
//   var_list = ABSENT | NC_VARIABLE nelems {name nelems {dimid} att_list nc_type vsize begin}
//   name     = nelems chars (padded to 4)
// Counts are 4 bytes (8 in CDF5); begin is 4 bytes in CDF1, 8 in CDF2 and CDF5.
#include "mesh/exodus_prescan.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <vector>

#include "mesh/exodus_shapes.hpp"
#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

constexpr std::uint64_t kMaxHeaderBytes = 16u << 20;

class Walk {
 public:
  Walk(const std::string& path, const std::string& bytes, std::uint64_t file_size)
      : path_(path), b_(bytes), file_size_(file_size) {}

  NetcdfHeader run() {
    if (b_.size() < 4 || b_.compare(0, 3, "CDF") != 0) fail("not a netCDF classic file");
    version_ = static_cast<unsigned char>(b_[3]);
    if (version_ != 1 && version_ != 2 && version_ != 5) fail("unknown netCDF classic version " + std::to_string(version_));
    at_ = 4;
    const std::uint64_t records = count();
    NetcdfHeader h;
    std::vector<std::uint64_t> lengths;
    std::vector<std::string> names;
    list(0x0A, [&] {
      names.push_back(name());
      lengths.push_back(count());
    });
    for (std::size_t i = 0; i < names.size(); ++i)  // netCDF names are unique (the libraries misread duplicates)
      if (!h.dimensions.emplace(names[i], lengths[i] == 0 ? records : lengths[i]).second)
        fail("the netCDF header is damaged (two dimensions named '" + names[i] + "')");
    list(0x0C, [&] { attribute(true); });
    list(0x0B, [&] { variable(lengths, names); });
    // The records: each holds at least the record variables' values; all but the last are complete in a
    // file of `records` records (the last may be partly written).
    const bool streaming = records == (version_ == 5 ? ~0ull : 0xFFFFFFFFull);
    if (!streaming && records > 1 && record_bytes_ > 0) {
      const long double end = record_begin_ + static_cast<long double>(records - 1) * record_bytes_;
      if (end > static_cast<long double>(file_size_))
        fail("truncated: the header states " + std::to_string(records) + " records (time steps), which need at least " +
             std::to_string(static_cast<unsigned long long>(end)) + " bytes, but the file has " +
             std::to_string(file_size_) + " (an interrupted copy or write?): copy or write it again");
    }
    if (!streaming && records > 0 && record_bytes_ > 0)
      h.records_end = static_cast<std::uint64_t>(record_begin_ + static_cast<long double>(records) * record_bytes_);
    h.file_size = file_size_;
    // ex_get_info reads len_line characters per record into buffers of 81 (the format's fixed length).
    if (const auto line = h.dimensions.find("len_line"); line != h.dimensions.end() && line->second > 81)
      fail("its dimension 'len_line' is " + std::to_string(line->second) + " where Exodus II has 81: a damaged or crafted file");
    // Exodus II: every file has these (ex_open needs them); a netCDF file without them is another kind.
    for (const char* d : {"num_dim", "num_nodes", "num_elem", "num_el_blk"})
      if (!h.dimensions.count(d))
        fail(std::string("a netCDF file, but not an Exodus II mesh (it has no dimension '") + d +
             "'); give a .exo/.g file written by Cubit, SEACAS or tribex, or a gmsh .msh file");
    return h;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw MeshError(path_ + ": " + what); }
  [[noreturn]] void cut() const {
    if (b_.size() >= kMaxHeaderBytes && file_size_ > kMaxHeaderBytes)
      fail("the netCDF header is larger than 16 MiB (the largest read); not a mesh tribex reads");
    fail("truncated: the file ends (" + std::to_string(file_size_) + " bytes) inside its netCDF header; the file was cut "
         "short (an interrupted copy or write?): copy or write it again");
  }
  std::uint64_t word(int n) {
    if (b_.size() - at_ < static_cast<std::size_t>(n) || at_ > b_.size()) cut();
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v = (v << 8) | static_cast<unsigned char>(b_[at_ + static_cast<std::size_t>(i)]);
    at_ += static_cast<std::size_t>(n);
    return v;
  }
  std::uint64_t count() { return word(version_ == 5 ? 8 : 4); }
  static std::string joined(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
    return s;
  }
  void skip(std::uint64_t n) {
    const std::uint64_t padded = n + (4 - n % 4) % 4;
    if (n > b_.size() || padded > b_.size() - at_) cut();
    at_ += static_cast<std::size_t>(padded);
  }
  std::string name() {
    const std::uint64_t n = count();
    if (n > 256) fail("a netCDF name of " + std::to_string(n) + " characters (netCDF allows 256); the header is damaged");
    if (n > b_.size() - at_) cut();
    std::string s = b_.substr(at_, static_cast<std::size_t>(n));
    // The C libraries end a name at a NUL: 'num_nodes\0_s' would be a second 'num_nodes' to them, and
    // Exodus would size the coordinates by one and read them by the other (a fuzz finding).
    if (const auto nul = s.find('\0'); nul != std::string::npos)
      fail("the netCDF header is damaged (the name '" + s.substr(0, nul) +
           "' is followed by a NUL byte and more characters; netCDF names hold none): a damaged or crafted file");
    skip(n);
    return s;
  }
  static std::uint64_t type_size(std::uint64_t type) {
    switch (type) {
      case 1: case 2: case 7: return 1;
      case 3: case 8: return 2;
      case 4: case 5: case 9: return 4;
      case 6: case 10: case 11: return 8;
      default: return 0;
    }
  }
  template <class F>
  void list(std::uint64_t tag, F&& item) {
    const std::uint64_t t = word(4), n = count();
    if (t == 0 && n == 0) return;  // ABSENT
    if (t != tag) fail("the netCDF header is damaged (a list tag " + std::to_string(t) + " where " + std::to_string(tag) + " belongs)");
    if (n > b_.size()) cut();  // each item takes at least 4 bytes of the header
    for (std::uint64_t i = 0; i < n; ++i) item();
  }
  /// One attribute; `global`: of the file, where Exodus reads some into a single value.
  void attribute(bool global) {
    const std::string att = name();
    const std::uint64_t size = type_size(word(4)), n = count();
    if (size == 0) fail("the netCDF header is damaged (an attribute of an unknown type)");
    if (n > b_.size()) cut();
    // ex_open reads these into one int or float on its stack: more values would overwrite it (a fuzz
    // finding: int64_status with 141 values, "stack smashing detected" inside ex_open).
    if (global && n != 1 && exodus_scalar_attribute(att))
      fail("its global attribute '" + att + "' holds " + std::to_string(n) +
           " values where Exodus II has one: a damaged or crafted file");
    // ex_get_block reads a block's element type into a buffer of MAX_STR_LENGTH + 1 (33) characters.
    if (!global && att == "elem_type" && n > 32)
      fail("an element type name of " + std::to_string(n) + " characters (Exodus II allows 32): a damaged or crafted file");
    skip(n * size);
  }
  void variable(const std::vector<std::uint64_t>& lengths, const std::vector<std::string>& dimension_names) {
    const std::string var = name();
    if (!variables_.insert(var).second) fail("the netCDF header is damaged (two variables named '" + var + "')");
    const std::uint64_t rank = count();
    if (rank > 1024) fail("variable '" + var + "' has " + std::to_string(rank) + " dimensions; the header is damaged");
    long double values = 1;
    bool record = false;
    std::vector<std::string> dims;
    for (std::uint64_t k = 0; k < rank; ++k) {
      const std::uint64_t id = count();
      if (id >= lengths.size()) fail("variable '" + var + "' refers to dimension " + std::to_string(id) + " of " + std::to_string(lengths.size()) + "; the header is damaged");
      if (lengths[id] == 0) record = true;
      else values *= static_cast<long double>(lengths[id]);
      dims.push_back(dimension_names[id]);
    }
    // The Exodus library sizes its reads of this variable by the format's dimensions, ours by the same.
    if (const auto expected = exodus_dimensions_of(var); !expected.empty() && dims != expected)
      fail("variable '" + var + "' has the dimensions (" + joined(dims) + ") where Exodus II has (" + joined(expected) +
           "): a damaged or crafted file");
    list(0x0C, [&] { attribute(false); });
    const std::uint64_t size = type_size(word(4));
    if (size == 0) fail("variable '" + var + "' has an unknown netCDF type; the header is damaged");
    count();  // vsize: not trusted (it saturates for > 4 GiB); the dimensions give the size
    const std::uint64_t begin = word(version_ == 1 ? 4 : 8);
    const long double end = static_cast<long double>(begin) + values * static_cast<long double>(size);
    // A record variable's data is per record: summed into one record's size (checked after the walk).
    if (record) {
      record_begin_ = std::min(record_begin_, static_cast<long double>(begin));
      record_bytes_ += values * static_cast<long double>(size);
    }
    if (!record && end > static_cast<long double>(file_size_)) {
      char b[240];
      std::snprintf(b, sizeof b, "variable '%s' (%.6Lg values) reaches byte %.6Lg, but the file has %llu bytes: ",
                    var.c_str(), values, end, static_cast<unsigned long long>(file_size_));
      const bool lying = end > 2.0L * static_cast<long double>(file_size_) + 1e6L;
      fail(std::string(b) + (lying ? "the header states sizes the file cannot hold (a damaged or crafted file)"
                                   : "truncated (an interrupted copy or write?): copy or write it again"));
    }
  }

  const std::string& path_;
  const std::string& b_;
  std::uint64_t file_size_;
  std::size_t at_ = 0;
  int version_ = 0;
  std::set<std::string> variables_;
  long double record_begin_ = 1e30L, record_bytes_ = 0;  // the first record variable's offset, one record's size
};

}  // namespace

NetcdfHeader prescan_netcdf_classic(const std::string& path, const std::string& bytes, std::uint64_t file_size) {
  return Walk(path, bytes, file_size).run();
}

NetcdfHeader prescan_exodus_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(std::max<std::streamoff>(in.tellg(), 0));
  in.seekg(0);
  std::string bytes(static_cast<std::size_t>(std::min(size, kMaxHeaderBytes)), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return prescan_netcdf_classic(path, bytes, size);
}

}  // namespace tribex::mesh
