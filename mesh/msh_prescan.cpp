// SPDX-License-Identifier: MIT
// MSH 4.1 layout walked here (gmsh reference manual, "MSH file format"):
//   $Entities: numPoints numCurves numSurfaces numVolumes, then per entity: tag, xyz (points) or a
//           bounding box, numPhysicalTags + tags, and (curves, surfaces, volumes) numBounding + tags
//   $Nodes: numEntityBlocks numNodes minNodeTag maxNodeTag, then per block
//           entityDim entityTag parametric(0/1) numNodesInBlock, the tags, then x y z (+ u v w) per node
//   $Elements: numEntityBlocks numElements minElementTag maxElementTag, then per block
//           entityDim entityTag elementType numElementsInBlock, then per element: tag node...
// Binary files store ints as int32 and counts/tags as size_t (data-size 8), native endian (int 1 first).
#include "mesh/msh_prescan.hpp"

#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string_view>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh {

namespace {

constexpr const char* corrupt_fix = "the file is corrupt: write it again from gmsh";

/// A token from a corrupt file, safe to put in a one-line message: printable ASCII, at most 20 chars.
std::string printable(std::string_view t) {
  std::string out;
  for (char ch : t.substr(0, 20)) out += ch >= 0x20 && ch < 0x7f ? ch : '?';
  if (t.size() > 20) out += "...";
  return out;
}

class Cursor {
 public:
  Cursor(const std::string& path, const std::string& data, std::size_t pos, bool binary)
      : path_(path), data_(data), pos_(pos), binary_(binary) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw MeshError(path_ + ": byte " + std::to_string(pos_) + ": " + what + "; " + corrupt_fix);
  }

  std::uint64_t size() { return binary_ ? raw<std::uint64_t>() : integer<std::uint64_t>(); }
  std::int64_t int32() { return binary_ ? raw<std::int32_t>() : integer<std::int64_t>(); }
  void skip_doubles(std::uint64_t n) {
    if (binary_) {
      if (n > (data_.size() - pos_) / 8) fail("section ends before its " + std::to_string(n) + " coordinates");
      pos_ += 8 * n;
      return;
    }
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::string_view t = token();
      double v = 0.0;
      const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
      if (ec != std::errc() || end != t.data() + t.size()) fail("expected a number, found '" + printable(t) + "'");
    }
  }
  /// The section must end here with `$End...` (after optional whitespace).
  void expect(const std::string& marker) {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    if (data_.compare(pos_, marker.size(), marker) != 0) fail("expected '" + marker + "' where the counts say the section ends");
  }
  std::size_t remaining() const { return data_.size() - pos_; }

 private:
  template <class T>
  T raw() {
    if (remaining() < sizeof(T)) fail("file ends inside a section");
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::string_view token() {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    if (start == pos_) fail("file ends inside a section");
    return std::string_view(data_).substr(start, pos_ - start);
  }
  template <class T>
  T integer() {
    const std::string_view t = token();
    T v{};
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
    if (ec != std::errc() || end != t.data() + t.size()) fail("expected an integer, found '" + printable(t) + "'");
    return v;
  }

  const std::string& path_;
  const std::string& data_;
  std::size_t pos_;
  bool binary_;
};

/// Position just after the line "$NAME", or npos.
std::size_t section_start(const std::string& data, const std::string& name) {
  const std::string marker = "\n$" + name;
  std::size_t at = data.find(marker + "\n");
  if (at == std::string::npos) at = data.find(marker + "\r\n");
  if (at == std::string::npos) return std::string::npos;
  return data.find('\n', at + 1) + 1;
}

void check_range(Cursor& c, const char* what, std::uint64_t tag, std::uint64_t lo, std::uint64_t hi) {
  if (tag < lo || tag > hi)
    c.fail(std::string(what) + " tag " + std::to_string(tag) + " is outside the declared range " + std::to_string(lo) +
           ".." + std::to_string(hi));
}

void check_header(Cursor& c, const char* section, std::uint64_t count, std::uint64_t lo, std::uint64_t hi) {
  // Tags index arrays in gmsh and in tribex (int): a range beyond 2^31 cannot be a real mesh here.
  constexpr std::uint64_t max_tag = std::numeric_limits<int>::max();
  if (count > 0 && (lo < 1 || hi < lo || hi > max_tag || hi - lo + 1 < count))
    c.fail(std::string(section) + " declares " + std::to_string(count) + " entries with tags " + std::to_string(lo) +
           ".." + std::to_string(hi) + ", which is impossible");
}

// One entity block's header in $Nodes or $Elements (MSH 4.1: entity dimension, entity tag, then the
// parametric flag or the element type, then the block's count).
struct EntityBlock {
  std::int64_t dim = 0;
  std::int64_t kind = 0;  // $Nodes: parametric (0 or 1); $Elements: the element type
  std::uint64_t n = 0;
};

EntityBlock entity_block(Cursor& c) {
  EntityBlock b;
  b.dim = c.int32();
  c.int32();  // entity tag
  b.kind = c.int32();
  b.n = c.size();
  return b;
}

// The blocks' counts against the section's declared total: more than declared fails at the block that
// passes it (`seen` so far), fewer at the section's end (check_total).
void count_block(Cursor& c, const char* section, const char* things, std::uint64_t n, std::uint64_t count,
                 std::uint64_t& seen) {
  if (n > count - seen)
    c.fail(std::string(section) + " blocks hold more " + things + " than the declared " + std::to_string(count));
  seen += n;
}

void check_total(Cursor& c, const char* section, const char* things, std::uint64_t seen, std::uint64_t count) {
  if (seen != count)
    c.fail(std::string(section) + " blocks hold " + std::to_string(seen) + " " + things + ", not the declared " +
           std::to_string(count));
}

}  // namespace

void prescan_msh41(const std::string& path, int (*nodes_per_element)(int type)) {
  std::ifstream in(path, std::ios::binary);
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t format = section_start("\n" + data.substr(0, 256), "MeshFormat");
  if (format == std::string::npos) return;  // check_file_is_msh already required the header
  const std::size_t after = format - 1;     // offset in `data` (we prefixed one newline)
  double version = 0.0;
  int file_type = 0, data_size = 0;
  {
    const std::size_t eol = data.find('\n', after);
    const std::string line = data.substr(after, eol == std::string::npos ? std::string::npos : eol - after);
    if (std::sscanf(line.c_str(), "%lf %d %d", &version, &file_type, &data_size) != 3)
      throw MeshError(path + ":2: the $MeshFormat line must be 'version file-type data-size'; " + corrupt_fix);
  }
  if (version < 4.05 || version > 4.15) return;  // only 4.1 is walked; gmsh reads 2.2 with its own checks
  const bool binary = file_type == 1;
  if (binary && data_size != 8)
    throw MeshError(path + ":2: binary MSH 4.1 with data-size " + std::to_string(data_size) + " (expected 8); " + corrupt_fix);
  if (binary) {
    const std::size_t one = data.find('\n', after) + 1;
    std::int32_t endian = 0;
    if (one + 4 <= data.size()) std::memcpy(&endian, data.data() + one, 4);
    if (endian != 1)
      throw MeshError(path + ": byte " + std::to_string(one) + ": binary mesh written with another byte order or corrupt; "
                      "write it again as ASCII (Mesh.Binary = 0)");
  }

  // $Entities: gmsh loops over the declared counts, so a corrupt count can stall it for minutes.
  const std::size_t entities_at = section_start(data, "Entities");
  if (entities_at != std::string::npos) {
    Cursor c(path, data, entities_at, binary);
    std::uint64_t counts[4];
    for (auto& n : counts) n = c.size();
    for (int dim = 0; dim < 4; ++dim)
      for (std::uint64_t i = 0; i < counts[dim]; ++i) {
        c.int32();                               // entity tag
        c.skip_doubles(dim == 0 ? 3 : 6);        // point xyz, or bounding box
        const std::uint64_t physicals = c.size();
        if (physicals > c.remaining()) c.fail("$Entities declares " + std::to_string(physicals) + " physical tags");
        for (std::uint64_t k = 0; k < physicals; ++k) c.int32();
        if (dim == 0) continue;
        const std::uint64_t bounding = c.size();
        if (bounding > c.remaining()) c.fail("$Entities declares " + std::to_string(bounding) + " bounding entities");
        for (std::uint64_t k = 0; k < bounding; ++k) c.int32();
      }
    c.expect("$EndEntities");
  }

  std::uint64_t min_node = 0, max_node = 0;
  const std::size_t nodes_at = section_start(data, "Nodes");
  if (nodes_at != std::string::npos) {
    Cursor c(path, data, nodes_at, binary);
    const std::uint64_t blocks = c.size(), count = c.size();
    min_node = c.size();
    max_node = c.size();
    check_header(c, "$Nodes", count, min_node, max_node);
    std::uint64_t seen = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const EntityBlock e = entity_block(c);  // kind: parametric
      if (e.dim < 0 || e.dim > 3 || e.kind < 0 || e.kind > 1) c.fail("$Nodes block header is invalid");
      count_block(c, "$Nodes", "nodes", e.n, count, seen);
      for (std::uint64_t i = 0; i < e.n; ++i) check_range(c, "node", c.size(), min_node, max_node);
      c.skip_doubles(e.n * (3 + static_cast<std::uint64_t>(e.kind * e.dim)));
    }
    check_total(c, "$Nodes", "nodes", seen, count);
    c.expect("$EndNodes");
  }

  const std::size_t elements_at = section_start(data, "Elements");
  if (elements_at != std::string::npos) {
    Cursor c(path, data, elements_at, binary);
    const std::uint64_t blocks = c.size(), count = c.size(), lo = c.size(), hi = c.size();
    check_header(c, "$Elements", count, lo, hi);
    std::uint64_t seen = 0;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const EntityBlock block = entity_block(c);  // kind: the element type
      const int per = block.kind > 0 && block.kind < 1000 ? nodes_per_element(static_cast<int>(block.kind)) : 0;
      if (block.dim < 0 || block.dim > 3 || per <= 0)
        c.fail("$Elements block has an unknown element type " + std::to_string(block.kind));
      count_block(c, "$Elements", "elements", block.n, count, seen);
      for (std::uint64_t e = 0; e < block.n; ++e) {
        check_range(c, "element", c.size(), lo, hi);
        for (int k = 0; k < per; ++k) check_range(c, "element node", c.size(), min_node, max_node);
      }
    }
    check_total(c, "$Elements", "elements", seen, count);
    c.expect("$EndElements");
  }
}

}  // namespace tribex::mesh
