// SPDX-License-Identifier: MIT
// msh_slices.hpp: an MSH 4.1 file walked once for an index, then read by ranges. The layout (gmsh reference
// manual, "MSH file format"; msh_prescan.cpp walks the same): $Entities gives each entity's physical tags;
// $Nodes and $Elements hold entity blocks (header, then the block's entries); binary files store ints as
// int32, counts and tags as size_t (data-size 8), doubles as 8 bytes, native endian.
#include "mesh/msh_slices.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <string_view>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh {
namespace {

constexpr int gmsh_hex8 = 5, gmsh_quad4 = 3;
// An ASCII block's entries have no fixed size: the walk notes the offset of every 4096th, so that a range is
// found by one seek and at most 4095 entries skipped (a range read alone costs its own size, not the block's
// earlier bytes: rank 0's hash reads the whole mesh in 65,536-entry chunks).
constexpr long long kMarkEvery = 4096;

// Nodes per gmsh element type (the first-order and the common second-order ones; gmsh's table); 0: unknown.
int nodes_of_type(long long type) {
  static constexpr int per[] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13};
  return type > 0 && type < static_cast<long long>(std::size(per)) ? per[type] : 0;
}

// The file through a 1 MiB buffer: tokens (ASCII) or raw values (binary), seekable, the byte offset known
// for messages. Holds nothing of the file beyond the buffer.
class Reader {
 public:
  Reader(const std::string& path, bool binary) : path_(path), binary_(binary), buf_(1 << 20) {
    f_ = std::fopen(path.c_str(), "rb");
    if (!f_) throw MeshError(path + ": cannot be opened for reading; check its permissions");
    if (fseeko(f_, 0, SEEK_END) != 0 || (size_ = ftello(f_)) < 0 || fseeko(f_, 0, SEEK_SET) != 0)
      throw MeshError(path + ": cannot be read (seek failed)");
  }
  ~Reader() { std::fclose(f_); }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  const std::string& fail_path() const { return path_; }
  void set_binary(bool binary) { binary_ = binary; }
  std::int64_t tell() const { return start_ + static_cast<std::int64_t>(at_); }
  void seek(std::int64_t offset) {
    if (offset >= start_ && offset <= start_ + static_cast<std::int64_t>(len_)) {
      at_ = static_cast<std::size_t>(offset - start_);  // inside the buffer: no read
      return;
    }
    if (offset > size_) {  // a count that skips past the end: a truncated file, said at its end
      start_ = size_;
      at_ = len_ = 0;
      fail("file ends inside a section");
    }
    if (fseeko(f_, offset, SEEK_SET) != 0) fail("cannot seek");
    start_ = offset;
    at_ = len_ = 0;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw MeshError(path_ + ": byte " + std::to_string(tell()) + ": " + what + "; the file is corrupt: write it again from gmsh");
  }
  int get() {
    if (at_ == len_ && !fill()) return EOF;
    return static_cast<unsigned char>(buf_[at_++]);
  }
  /// The next line without its end of line; false at the end of the file.
  bool line(std::string& out) {
    out.clear();
    int c = get();
    if (c == EOF) return false;
    for (; c != EOF && c != '\n'; c = get()) out += static_cast<char>(c);
    if (!out.empty() && out.back() == '\r') out.pop_back();
    return true;
  }
  std::string_view token() {
    int c = get();
    while (c != EOF && std::isspace(c)) c = get();
    tok_.clear();
    for (; c != EOF && !std::isspace(c); c = get()) tok_ += static_cast<char>(c);
    if (tok_.empty()) fail("file ends inside a section");
    return tok_;
  }
  std::uint64_t size() { return binary_ ? raw<std::uint64_t>() : text_size(); }
  std::uint64_t text_size() { return number<std::uint64_t>("an integer"); }  // ASCII in either kind of file
  std::int64_t int32() { return binary_ ? raw<std::int32_t>() : number<std::int64_t>("an integer"); }
  double real() { return binary_ ? raw<double>() : number<double>("a number"); }
  /// Skips `n` values of `bytes` each (binary) or `n` tokens (ASCII).
  void skip(std::uint64_t n, std::uint64_t bytes) {
    if (binary_) return seek(tell() + static_cast<std::int64_t>(n * bytes));
    for (std::uint64_t i = 0; i < n; ++i) token();
  }

 private:
  bool fill() {
    start_ += static_cast<std::int64_t>(len_);
    len_ = std::fread(buf_.data(), 1, buf_.size(), f_);
    at_ = 0;
    return len_ > 0;
  }
  template <class T>
  T raw() {
    T v;
    char* p = reinterpret_cast<char*>(&v);
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      const int c = get();
      if (c == EOF) fail("file ends inside a section");
      p[i] = static_cast<char>(c);
    }
    return v;
  }
  template <class T>
  T number(const char* what) {
    const std::string_view t = token();
    T v{};
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size())
      fail(std::string("expected ") + what + ", found '" + std::string(t.substr(0, 20)) + "'");
    return v;
  }

  const std::string& path_;
  bool binary_;
  std::FILE* f_ = nullptr;
  std::vector<char> buf_;
  std::int64_t start_ = 0;  // the file offset of buf_[0]
  std::int64_t size_ = 0;   // the file's
  std::size_t at_ = 0, len_ = 0;
  std::string tok_;
};

// What the walk keeps: the index, and the first reason the file cannot be sliced.
struct Walk {
  std::map<std::pair<int, int>, std::string> names;          // (dim, physical tag) -> name
  std::map<std::pair<int, int>, std::vector<int>> physicals;  // (dim, entity tag) -> physical tags
  std::vector<MshSlices::EntityBlock> nodes, elements;
  std::vector<std::int64_t> marks;  // ASCII: see kMarkEvery
  bool binary = false;
  std::uint64_t max_node = 0;
  std::string unsupported;
};

void section_end(Reader& r, const std::string& name) {
  if (r.token() != "$End" + name) r.fail("expected '$End" + name + "' where the counts say the section ends");
}

void check_header(Reader& r, const char* section, std::uint64_t count, std::uint64_t lo, std::uint64_t hi) {
  constexpr std::uint64_t max_tag = std::numeric_limits<int>::max();  // tags index int arrays (msh_prescan)
  if (count > 0 && (lo < 1 || hi < lo || hi > max_tag || hi - lo + 1 < count))
    r.fail(std::string(section) + " declares " + std::to_string(count) + " entries with tags " + std::to_string(lo) +
           ".." + std::to_string(hi) + ", which is impossible");
}

void check_range(Reader& r, const char* what, std::uint64_t tag, std::uint64_t lo, std::uint64_t hi) {
  if (tag < lo || tag > hi)
    r.fail(std::string(what) + " tag " + std::to_string(tag) + " is outside the declared range " + std::to_string(lo) +
           ".." + std::to_string(hi));
}

// $PhysicalNames (ASCII in both kinds of file): count, then `dim tag "name"` per line.
void read_names(Reader& r, Walk& w) {
  const std::uint64_t n = r.text_size();
  std::string text;
  for (std::uint64_t i = 0; i < n; ++i) {
    do  // the count's token took its end of line; blank lines skipped
      if (!r.line(text)) r.fail("file ends inside $PhysicalNames");
    while (text.find_first_not_of(" \t") == std::string::npos);
    int dim = 0, tag = 0, used = 0;
    const std::size_t q = text.find('"'), e = text.rfind('"');
    if (std::sscanf(text.c_str(), "%d %d %n", &dim, &tag, &used) < 2 || q == std::string::npos || e <= q)
      r.fail("a $PhysicalNames line must be 'dim tag \"name\"'");
    w.names[{dim, tag}] = text.substr(q + 1, e - q - 1);
  }
}

// $Entities: counts per dimension, then per entity its tag, point or box, physical tags and (dim > 0) bounding
// entities; only the physical tags are kept.
void read_entities(Reader& r, Walk& w) {
  std::uint64_t counts[4];
  for (auto& n : counts) n = r.size();
  for (int dim = 0; dim < 4; ++dim)
    for (std::uint64_t i = 0; i < counts[dim]; ++i) {
      const int tag = static_cast<int>(r.int32());
      for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) r.real();
      const std::uint64_t physicals = r.size();
      if (physicals > 1000000) r.fail("$Entities declares " + std::to_string(physicals) + " physical tags");
      std::vector<int>& p = w.physicals[{dim, tag}];
      for (std::uint64_t k = 0; k < physicals; ++k) p.push_back(static_cast<int>(r.int32()));
      if (dim == 0) continue;
      const std::uint64_t bounding = r.size();
      if (bounding > 1000000) r.fail("$Entities declares " + std::to_string(bounding) + " bounding entities");
      r.skip(bounding, 4);
    }
}

MshSlices::EntityBlock block_header(Reader& r, const char* section, std::uint64_t count, std::uint64_t& seen) {
  MshSlices::EntityBlock b;
  const std::int64_t dim = r.int32(), entity = r.int32(), kind = r.int32();
  b.n = static_cast<long long>(r.size());
  if (dim < 0 || dim > 3) r.fail(std::string(section) + " block header is invalid");
  if (static_cast<std::uint64_t>(b.n) > count - seen)
    r.fail(std::string(section) + " blocks hold more entries than the declared " + std::to_string(count));
  seen += static_cast<std::uint64_t>(b.n);
  b.dim = static_cast<int>(dim);
  b.entity = static_cast<int>(entity);
  b.type = static_cast<int>(kind);
  return b;
}

// $Nodes: per block its tags (one contiguous run is what slicing needs) then x y z (+ u v w) per node.
void read_nodes(Reader& r, Walk& w) {
  const std::uint64_t blocks = r.size(), count = r.size(), lo = r.size(), hi = r.size();
  check_header(r, "$Nodes", count, lo, hi);
  w.max_node = hi;
  std::uint64_t seen = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    MshSlices::EntityBlock e = block_header(r, "$Nodes", count, seen);
    if (e.type < 0 || e.type > 1) r.fail("$Nodes block header is invalid");
    e.per = 3 + e.type * e.dim;
    e.type = 0;
    for (long long i = 0; i < e.n; ++i) {
      const auto t = static_cast<long long>(r.size());
      check_range(r, "node", static_cast<std::uint64_t>(t), lo, hi);
      if (i == 0) e.first_tag = t;
      else e.ascending = e.ascending && t == e.last_tag + 1;
      e.last_tag = t;
    }
    e.at = r.tell();
    e.mark = static_cast<long long>(w.marks.size());
    if (w.binary) r.skip(static_cast<std::uint64_t>(e.n * e.per), 8);
    for (long long i = 0; !w.binary && i < e.n; ++i) {
      if (i % kMarkEvery == 0) w.marks.push_back(r.tell());
      r.skip(static_cast<std::uint64_t>(e.per), 8);
    }
    w.nodes.push_back(e);
  }
  if (seen != count) r.fail("$Nodes blocks hold " + std::to_string(seen) + " nodes, not the declared " + std::to_string(count));
}

// $Elements: per block its elements (tag, nodes); types this does not know leave the file to the serial reader.
void read_element_section(Reader& r, Walk& w) {
  const std::uint64_t blocks = r.size(), count = r.size(), lo = r.size(), hi = r.size();
  check_header(r, "$Elements", count, lo, hi);
  std::uint64_t seen = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    MshSlices::EntityBlock e = block_header(r, "$Elements", count, seen);
    e.per = nodes_of_type(e.type);
    if (e.per == 0) {
      w.unsupported = "elements of gmsh type " + std::to_string(e.type);
      return;
    }
    e.at = r.tell();
    e.mark = static_cast<long long>(w.marks.size());
    for (long long i = 0; i < e.n; ++i) {
      if (!w.binary && i % kMarkEvery == 0) w.marks.push_back(r.tell());
      const auto t = static_cast<long long>(r.size());
      check_range(r, "element", static_cast<std::uint64_t>(t), lo, hi);
      if (i == 0) e.first_tag = t;
      else e.ascending = e.ascending && t > e.last_tag;
      e.last_tag = t;
      for (int k = 0; k < e.per; ++k) check_range(r, "element node", r.size(), 1, w.max_node);
    }
    w.elements.push_back(e);
  }
  if (seen != count)
    r.fail("$Elements blocks hold " + std::to_string(seen) + " elements, not the declared " + std::to_string(count));
}

// The $MeshFormat line: "" for 4.1 (`binary` set, the binary one's endianness checked), else the reason.
std::string read_format(Reader& r, bool& binary) {
  std::string text;
  while (r.line(text) && text.find_first_not_of(" \t") == std::string::npos) {
  }
  if (text.find("$MeshFormat") == std::string::npos)
    throw MeshError(r.fail_path() + ":1: not a gmsh mesh file (expected '$MeshFormat')");
  double version = 0.0;
  int file_type = 0, data_size = 0;
  if (!r.line(text) || std::sscanf(text.c_str(), "%lf %d %d", &version, &file_type, &data_size) != 3)
    throw MeshError(r.fail_path() + ":2: the $MeshFormat line must be 'version file-type data-size'; the file is corrupt: write it again from gmsh");
  if (version < 4.05 || version > 4.15) return "MSH version " + text.substr(0, text.find(' ')) + " (4.1 is read in slices)";
  binary = file_type == 1;
  r.set_binary(binary);
  if (binary && data_size != 8) return "binary MSH with data-size " + std::to_string(data_size);
  if (binary) {
    std::int32_t one = 0;
    for (int i = 0; i < 4; ++i) reinterpret_cast<char*>(&one)[i] = static_cast<char>(r.get());
    if (one != 1) r.fail("binary mesh written with another byte order");
  }
  section_end(r, "MeshFormat");
  return "";
}

// To entry k of block e, `tokens` values each: binary entries have a fixed size; an ASCII block's nearest mark
// at or before k, then the entries after it skipped.
void seek_entry(Reader& r, bool binary, const std::vector<std::int64_t>& marks, const MshSlices::EntityBlock& e,
                long long k, int tokens) {
  if (binary) return r.seek(e.at + k * tokens * 8);
  const long long m = k / kMarkEvery;
  r.seek(marks.at(static_cast<std::size_t>(e.mark + m)));
  r.skip(static_cast<std::uint64_t>((k - m * kMarkEvery) * tokens), 8);
}

// The index as bytes and back (every member below; the same binary on every rank, so plain copies).
struct Pack {
  std::string bytes;
  template <class T>
  void pod(const T& v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    pod(v.size());
    bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void str(const std::string& v) {
    pod(v.size());
    bytes += v;
  }
};

struct Unpack {
  const std::string& bytes;
  std::size_t at = 0;
  template <class T>
  void pod(T& v) {
    if (at + sizeof v > bytes.size()) throw MeshError("a gmsh index that is cut short");
    std::memcpy(&v, bytes.data() + at, sizeof v);
    at += sizeof v;
  }
  template <class T>
  void vec(std::vector<T>& v) {
    std::size_t n = 0;
    pod(n);
    if (n > (bytes.size() - at) / sizeof(T)) throw MeshError("a gmsh index that is cut short");
    v.resize(n);
    if (n > 0) std::memcpy(v.data(), bytes.data() + at, n * sizeof(T));  // an empty vector's data() may be null
    at += n * sizeof(T);
  }
  void str(std::string& v) {
    std::size_t n = 0;
    pod(n);
    if (n > bytes.size() - at) throw MeshError("a gmsh index that is cut short");
    v = bytes.substr(at, n);
    at += n;
  }
};

}  // namespace

MshSlices::MshSlices(const std::string& path) : path_(path) {
  Reader r(path, false);
  unsupported_ = read_format(r, binary_);
  if (!unsupported_.empty()) return;
  Walk w;
  w.binary = binary_;
  std::string text;
  while (w.unsupported.empty() && r.line(text)) {
    if (text.empty() || text[0] != '$') continue;
    const std::string name = text.substr(1);
    if (name == "PhysicalNames") read_names(r, w);
    else if (name == "Entities") read_entities(r, w);
    else if (name == "Nodes") read_nodes(r, w);
    else if (name == "Elements") read_element_section(r, w);
    else if (name == "PartitionedEntities") w.unsupported = "a partitioned mesh";
    else {  // a section tribex does not use ($Periodic, $NodeData, ...): to its end marker
      while (r.line(text) && text != "$End" + name) {
      }
      continue;
    }
    if (w.unsupported.empty()) section_end(r, name);
  }
  unsupported_ = w.unsupported;
  if (!unsupported_.empty()) return;
  // Slicing numbers node tag t as node t - 1: the blocks' tags must be runs that tile 1..N.
  std::sort(w.nodes.begin(), w.nodes.end(), [](const EntityBlock& a, const EntityBlock& b) { return a.first_tag < b.first_tag; });
  long long next = 1;
  for (const EntityBlock& b : w.nodes) {
    if (b.n == 0) continue;
    if (!b.ascending || b.first_tag != next) unsupported_ = "node tags that are not contiguous runs per entity block covering 1..N";
    next = b.last_tag + 1;
  }
  if (!unsupported_.empty()) return;
  node_count_ = static_cast<int>(next - 1);
  nodes_ = std::move(w.nodes);
  elements_ = std::move(w.elements);
  marks_ = std::move(w.marks);
  // The physical groups as gmsh lists them: each (dim, tag) some entity carries, by (dim, tag).
  std::map<std::pair<int, int>, Group> groups;
  for (const auto& [entity, tags] : w.physicals)
    for (int tag : tags) {
      Group& g = groups[{entity.first, tag}];
      g.dim = entity.first;
      g.tag = tag;
      const auto named = w.names.find({entity.first, tag});
      g.name = named != w.names.end() && !named->second.empty()
                   ? named->second
                   : (g.dim == 3 ? "block_" : g.dim == 2 ? "surface_" : "nodes_") + std::to_string(tag);
      for (std::size_t b = 0; b < elements_.size(); ++b)
        if (elements_[b].dim == entity.first && elements_[b].entity == entity.second) g.blocks.push_back(b);
    }
  std::vector<Group> list;
  for (auto& [key, g] : groups) list.push_back(std::move(g));
  index(list);
}

void MshSlices::index(const std::vector<Group>& groups) {
  std::vector<Group> volumes;
  for (const Group& g : groups)
    if (g.dim == 3) volumes.push_back(g);
  index_volumes(std::move(volumes));
  if (!unsupported_.empty()) return;
  index_sets(groups, 2, side_sets_, side_set_blocks_);
  index_sets(groups, 0, node_sets_, node_set_blocks_);
}

// Blocks as read_gmsh makes them: the 3-D groups by tag (none: one "block_1" of every volume), each block's
// hexes by element tag. Sliceable where each group's hex blocks are ascending runs that do not interleave.
void MshSlices::index_volumes(std::vector<Group> volumes) {
  std::vector<int> holders(elements_.size(), 0);
  for (std::size_t b = 0; b < elements_.size(); ++b) {
    const EntityBlock& e = elements_[b];
    if (e.dim == 3 && e.n > 0 && e.type != gmsh_hex8) unsupported_ = "volume elements that are not hex8";
  }
  if (volumes.empty()) {
    Group all{3, 1, "block_1", {}};
    for (std::size_t b = 0; b < elements_.size(); ++b)
      if (elements_[b].dim == 3) all.blocks.push_back(b);
    volumes.push_back(all);
  }
  for (Group& g : volumes) {
    std::vector<std::size_t> hexes;
    for (std::size_t b : g.blocks)
      if (elements_[b].n > 0 && elements_[b].type == gmsh_hex8) hexes.push_back(b), ++holders[b];
    std::sort(hexes.begin(), hexes.end(),
              [&](std::size_t a, std::size_t b) { return elements_[a].first_tag < elements_[b].first_tag; });
    const int first = static_cast<int>(hex_first_.empty() ? 0 : hex_first_.back());
    long long count = 0, last = 0;
    for (std::size_t b : hexes) {
      if (!elements_[b].ascending || (count > 0 && elements_[b].first_tag <= last))
        unsupported_ = "hex tags of volume '" + g.name + "' that are not ascending runs per entity block";
      last = elements_[b].last_tag;
      if (hex_first_.empty()) hex_first_.push_back(0);
      hexes_.push_back(b);
      hex_first_.push_back(hex_first_.back() + elements_[b].n);
      count += elements_[b].n;
    }
    blocks_.push_back({g.name, first, static_cast<int>(count)});
  }
  for (std::size_t b = 0; b < elements_.size(); ++b)
    if (elements_[b].dim == 3 && elements_[b].n > 0 && holders[b] != 1)
      unsupported_ = holders[b] == 0 ? "hexes in no physical volume" : "an entity in two physical volumes";
  element_count_ = static_cast<int>(hex_first_.empty() ? 0 : hex_first_.back());
  if (element_count_ == 0) unsupported_ = "no hex elements";
  // The source orders a side set's sides by element * 6 + face, an int.
  if (element_count_ > std::numeric_limits<int>::max() / 6) unsupported_ = "more than 357,913,941 hexes";
}

// The 2-D groups (dim 2) as side sets, or the 0-D and 1-D ones (dim 0) as node sets, by (dim, tag); an entry is
// one element of the group's entities.
void MshSlices::index_sets(const std::vector<Group>& groups, int dim, exodus::SetOutline& sets,
                           std::vector<std::vector<std::size_t>>& blocks) {
  for (const Group& g : groups) {
    if (dim == 2 ? g.dim != 2 : g.dim > 1) continue;
    if (std::find(sets.names.begin(), sets.names.end(), g.name) != sets.names.end())
      unsupported_ = "two physical groups named '" + g.name + "'";
    long long entries = 0;
    for (std::size_t b : g.blocks) {
      if (dim == 2 && elements_[b].n > 0 && elements_[b].type != gmsh_quad4) unsupported_ = "surface elements that are not quad4";
      entries += elements_[b].n;
    }
    sets.names.push_back(g.name);
    sets.ids.push_back(g.tag);
    sets.entries.push_back(entries);
    blocks.push_back(g.blocks);
  }
}

std::vector<long long> MshSlices::read_elements(const std::vector<std::size_t>& blocks, long long first,
                                                long long count) const {
  if (!unsupported_.empty()) throw MeshError(path_ + ": cannot be read in slices (" + unsupported_ + ")");
  Reader r(path_, binary_);
  std::vector<long long> out;
  long long start = 0;  // the first entry of block b in the concatenation
  for (std::size_t b : blocks) {
    const EntityBlock& e = elements_[b];
    const long long lo = std::max(first, start), hi = std::min(first + count, start + e.n);
    if (lo < hi) {
      seek_entry(r, binary_, marks_, e, lo - start, 1 + e.per);
      for (long long k = lo; k < hi; ++k)
        for (int j = 0; j <= e.per; ++j) out.push_back(static_cast<long long>(r.size()));
    }
    start += e.n;
  }
  return out;
}

std::vector<int> MshSlices::connectivity(int first, int count) const {
  const std::vector<long long> raw = read_elements(hexes_, first, count);
  std::vector<int> c;
  c.reserve(8 * static_cast<std::size_t>(count));
  for (std::size_t k = 0; k < raw.size(); k += 9)
    for (int a = 1; a <= 8; ++a) c.push_back(static_cast<int>(raw[k + a] - 1));  // tags checked by the walk
  for (int n : c)
    if (n >= node_count_) throw MeshError(path_ + ": a hex refers to node tag " + std::to_string(n + 1) + ", which has no coordinates");
  return c;
}

std::vector<double> MshSlices::coordinates(int first, int count) const {
  if (!unsupported_.empty()) throw MeshError(path_ + ": cannot be read in slices (" + unsupported_ + ")");
  Reader r(path_, binary_);
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<std::size_t>(count));
  for (const EntityBlock& e : nodes_) {  // by first tag: node t - 1
    const long long start = e.first_tag - 1;
    const long long lo = std::max<long long>(first, start), hi = std::min<long long>(first + count, start + e.n);
    if (lo >= hi) continue;
    seek_entry(r, binary_, marks_, e, lo - start, e.per);
    for (long long k = lo; k < hi; ++k) {
      for (int i = 0; i < 3; ++i) xyz.push_back(r.real());
      r.skip(static_cast<std::uint64_t>(e.per - 3), 8);
    }
  }
  return xyz;
}

std::vector<int> MshSlices::node_set(std::size_t set, long long first, long long count) const {
  std::vector<int> nodes;
  const auto& blocks = node_set_blocks_[set];
  const std::vector<long long> raw = read_elements(blocks, first, count);
  // Each entry is one element: its tag, then its nodes (the blocks' kinds may differ: walk them as read).
  long long start = 0;
  std::size_t k = 0;
  for (std::size_t b : blocks) {
    const EntityBlock& e = elements_[b];
    const long long lo = std::max(first, start), hi = std::min(first + count, start + e.n);
    for (long long i = lo; i < hi; ++i, k += 1 + static_cast<std::size_t>(e.per))
      for (int j = 1; j <= e.per; ++j) nodes.push_back(static_cast<int>(raw[k + static_cast<std::size_t>(j)] - 1));
    start += e.n;
  }
  return nodes;
}

std::vector<Side> MshSlices::side_set(std::size_t, long long, long long) const {
  throw MeshError(path_ + ": a gmsh file's side sets are quads, matched to hex faces by the set-up");
}

std::vector<int> MshSlices::quads(std::size_t set, long long first, long long count) const {
  const std::vector<long long> raw = read_elements(side_set_blocks_[set], first, count);
  std::vector<int> q(raw.size());
  for (std::size_t k = 0; k < raw.size(); ++k) q[k] = static_cast<int>(k % 5 == 0 ? raw[k] : raw[k] - 1);
  return q;
}

// Every member the reads use, in one list for both directions.
template <class Archive>
void MshSlices::fields(Archive& a) {
  a.str(unsupported_);
  a.pod(binary_);
  a.pod(node_count_);
  a.pod(element_count_);
  a.vec(nodes_);
  a.vec(elements_);
  a.vec(marks_);
  a.vec(hexes_);
  a.vec(hex_first_);
  std::size_t n = blocks_.size();
  a.pod(n);
  blocks_.resize(n);
  for (Block& b : blocks_) {
    a.str(b.name);
    a.pod(b.first_element);
    a.pod(b.element_count);
  }
  for (exodus::SetOutline* sets : {&node_sets_, &side_sets_}) {
    n = sets->names.size();
    a.pod(n);
    sets->names.resize(n);
    for (std::string& name : sets->names) a.str(name);
    a.vec(sets->ids);
    a.vec(sets->entries);
  }
  for (auto* blocks : {&node_set_blocks_, &side_set_blocks_}) {
    n = blocks->size();
    a.pod(n);
    blocks->resize(n);
    for (auto& b : *blocks) a.vec(b);
  }
}

std::string MshSlices::index() const {
  Pack p;
  const_cast<MshSlices*>(this)->fields(p);  // Pack only reads (the resizes keep the sizes)
  return p.bytes;
}

MshSlices::MshSlices(const std::string& path, const std::string& index) : path_(path) {
  Unpack u{index};
  fields(u);
}

}  // namespace tribex::mesh
