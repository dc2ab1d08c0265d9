// SPDX-License-Identifier: MIT
// Exodus II mesh read/write (mesh/README.md, "Exodus II mapping rules").
#include "mesh/exodus_io.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesh/exodus_prescan.hpp"
#include "mesh/exodus_shapes.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/output_target.hpp"

namespace tribex::mesh {
namespace {

// Exodus prints its errors to stderr unless told not to; tribex reports them itself, one line.
// (ex_opts is the library's one global switch; EX_DEFAULT = neither verbose nor abort.)
void quiet_exodus() { ex_opts(EX_DEFAULT); }

[[noreturn]] void fail(const std::string& path, const std::string& what) { throw MeshError(path + ": " + what); }

std::string reason() {
  const std::string e = exodus::last_error();
  return e.empty() ? std::string() : " (" + e + ")";
}

// An open Exodus file, closed on scope exit.
struct ExoFile {
  int id = -1;
  ~ExoFile() {
    if (id >= 0) ex_close(id);
  }
};

// The netCDF flavour from the first bytes (netCDF's own signatures), or "" for anything else.
// Checked before the library sees the file: a file that is not netCDF gets a clear message
// instead of the library's.
std::string netcdf_kind(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char b[8] = {};
  in.read(b, 8);
  if (in.gcount() >= 4 && b[0] == 'C' && b[1] == 'D' && b[2] == 'F') {
    if (b[3] == 1) return "classic";
    if (b[3] == 2) return "64-bit offset";
    if (b[3] == 5) return "CDF5";
  }
  if (in.gcount() == 8 && std::memcmp(b, "\x89HDF\r\n\x1a\n", 8) == 0) return "netCDF-4";
  return "";
}

// Bounds of what read_exodus allocates (issue 54, item 11; mesh/README.md): names as netCDF allows them,
// element and node counts whose connectivity and coordinate indices fit an int.
constexpr long long kMaxNameLength = 256;
constexpr int kMaxElements = (1 << 28) - 1;  // 8 x elements < 2^31
constexpr int kMaxNodes = 715'827'882;       // 3 x nodes < 2^31

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Entity names as stored (up to the file's longest), "" where the file has none.
std::vector<std::string> entity_names(int exo, ex_entity_type type, std::size_t count, int length) {
  std::vector<std::vector<char>> buffers(count, std::vector<char>(static_cast<std::size_t>(length) + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& b : buffers) pointers.push_back(b.data());
  std::vector<std::string> names(count);
  if (count > 0 && ex_get_names(exo, type, pointers.data()) >= 0)
    for (std::size_t i = 0; i < count; ++i) names[i] = buffers[i].data();
  return names;
}

std::vector<int> entity_ids(int exo, ex_entity_type type, int count, const std::string& path, const char* what) {
  std::vector<int> ids(static_cast<std::size_t>(count));
  if (count > 0 && ex_get_ids(exo, type, ids.data()) < 0) fail(path, std::string("cannot read the ") + what + " ids" + reason());
  return ids;
}

int put_names(int exo, ex_entity_type type, const std::vector<std::string>& names) {
  if (names.empty()) return 0;
  std::vector<char*> p;
  for (const auto& n : names) p.push_back(const_cast<char*>(n.c_str()));  // the API takes char**; it only reads
  return ex_put_names(exo, type, p.data());
}

/// The entries of set `id` of a node or side set (`what` names it in errors): the node or element
/// numbers, and for a side set the side numbers (empty for a node set). 1-based, as in the file.
std::pair<std::vector<int>, std::vector<int>> set_entries(int exo, ex_entity_type type, int id, const std::string& path,
                                                          const std::string& what) {
  int count = 0, factors = 0;
  if (ex_get_set_param(exo, type, id, &count, &factors) < 0) fail(path, "cannot read " + what + reason());
  std::vector<int> entries(static_cast<std::size_t>(count)), sides(type == EX_SIDE_SET ? entries.size() : 0);
  if (count > 0 && ex_get_set(exo, type, id, entries.data(), type == EX_SIDE_SET ? sides.data() : nullptr) < 0)
    fail(path, "cannot read " + what + reason());
  return {std::move(entries), std::move(sides)};
}

// The element blocks in file order (empty ones dropped), each checked HEX8, with their element ranges: Exodus
// numbers elements block after block. The block count is checked against the header's element count.
void read_blocks(int exo, const std::string& path, int nblocks, exodus::Header& h) {
  h.block_ids = entity_ids(exo, EX_ELEM_BLOCK, nblocks, path, "element block");
  const auto names = entity_names(exo, EX_ELEM_BLOCK, h.block_ids.size(), h.name_length);
  std::vector<int> kept;
  int at = 0;
  for (std::size_t b = 0; b < h.block_ids.size(); ++b) {
    char type[MAX_STR_LENGTH + 1] = {};
    int count = 0, per = 0, edges = 0, faces = 0, attrs = 0;
    if (ex_get_block(exo, EX_ELEM_BLOCK, h.block_ids[b], type, &count, &per, &edges, &faces, &attrs) < 0)
      fail(path, "cannot read element block " + std::to_string(h.block_ids[b]) + reason());
    const std::string name = names[b].empty() ? "block_" + std::to_string(h.block_ids[b]) : names[b];
    if (count == 0) continue;  // an empty block holds no element: dropped
    const std::string t = lower(type);
    if (per != 8 || (t != "hex" && t != "hex8" && t != "hexahedron"))
      fail(path, "element block '" + name + "' (id " + std::to_string(h.block_ids[b]) + ") has " + std::to_string(count) +
                     " " + type + " elements with " + std::to_string(per) +
                     " nodes; tribex needs HEX8 only: re-mesh it all-hex, first order (Cubit: block " +
                     std::to_string(h.block_ids[b]) + " element type hex8)");
    if (count < 0 || count > h.elements - at)
      fail(path, "the blocks hold more elements than the header's " + std::to_string(h.elements) + "; the file is inconsistent");
    h.blocks.push_back({name, at, count});
    kept.push_back(h.block_ids[b]);
    at += count;
  }
  h.block_ids = std::move(kept);
  if (at != h.elements)
    fail(path, "the blocks hold " + std::to_string(at) + " elements but the header says " + std::to_string(h.elements) +
                   "; the file is inconsistent");
}

}  // namespace

ExodusLengthUnit exodus::length_unit_of(int exo, const std::string& path) {
  ExodusLengthUnit unit;
  const int count = static_cast<int>(ex_inquire_int(exo, EX_INQ_INFO));
  if (count <= 0) return unit;
  std::vector<std::vector<char>> lines(static_cast<std::size_t>(count), std::vector<char>(MAX_LINE_LENGTH + 1, '\0'));
  std::vector<char*> p;
  for (auto& l : lines) p.push_back(l.data());
  if (ex_get_info(exo, p.data()) < 0) return unit;  // unreadable notes: no unit named
  const std::string key = exodus_length_unit_record;
  for (const auto& l : lines) {
    const std::string line(l.data());
    if (line.rfind(key, 0) != 0) continue;
    unit.name = line.substr(key.size());
    unit.name.erase(unit.name.find_last_not_of(' ') + 1);
    if (unit.name == "m") unit.per_metre = 1.0;
    else if (unit.name == "um") unit.per_metre = 1e6;
    else if (unit.name == "nm") unit.per_metre = 1e9;
    else
      fail(path, "its info record '" + line + "' names a length unit other than m, um or nm; write the file in one of them");
  }
  return unit;
}

bool is_exodus_path(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  return ext == ".exo" || ext == ".e" || ext == ".g" || ext == ".gen";
}

std::string exodus::last_error() {
  const char* msg = nullptr;
  const char* func = nullptr;
  int code = 0;
  ex_get_err(&msg, &func, &code);
  std::string m = msg ? msg : "";
  while (!m.empty() && (m.back() == '\n' || m.back() == ' ')) m.pop_back();
  std::replace(m.begin(), m.end(), '\n', ' ');
  return m;
}

exodus::Header exodus::open_checked(const std::string& path, bool walk_header) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(path, "no such file; check 'database name' (relative to the deck)");
  if (!fs::is_regular_file(path, ec)) fail(path, "not a regular file; give the Exodus II mesh file");
  Header h;
  h.kind = netcdf_kind(path);
  if (h.kind.empty())
    fail(path, "not an Exodus II file (no netCDF signature in its first bytes, " + std::to_string(fs::file_size(path, ec)) +
                   " bytes); give a .exo/.g file written by Cubit, SEACAS or tribex, or a gmsh .msh file");
  // Every size the header states, checked against the file before the library allocates for it.
  if (walk_header && h.kind != "netCDF-4") prescan_exodus_file(path);
  else if (walk_header) check_netcdf4_exodus(path);
  quiet_exodus();
  int comp_ws = sizeof(double), io_ws = 0;
  float version = 0;
  ExoFile f;
  f.id = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
  if (f.id < 0) fail(path, "the Exodus II library cannot open this " + h.kind + " netCDF file" + reason() + "; is it truncated?");
  const int exo = f.id;
  const auto used_name_length = ex_inquire_int(exo, EX_INQ_DB_MAX_USED_NAME_LENGTH);
  if (used_name_length > kMaxNameLength)
    fail(path, "the header states names of up to " + std::to_string(used_name_length) + " characters "
               "(maximum_name_length); Exodus II allows " + std::to_string(kMaxNameLength) + ": a damaged or crafted file");
  h.name_length = std::max<int>(static_cast<int>(used_name_length), 32);
  ex_set_max_name_length(exo, h.name_length);

  char title[MAX_LINE_LENGTH + 1] = {};
  int dim = 0, nblocks = 0;
  if (ex_get_init(exo, title, &dim, &h.nodes, &h.elements, &nblocks, &h.node_sets, &h.side_sets) < 0)
    fail(path, "cannot read the Exodus II header" + reason());
  const int nodes = h.nodes, elements = h.elements;
  if (dim != 3) fail(path, "a " + std::to_string(dim) + "-D mesh; tribex needs a 3-D all-hex (HEX8) mesh");
  if (nodes <= 0 || elements <= 0) fail(path, "the file has no nodes or no elements; give a 3-D HEX8 mesh");
  // A classic file stores every element's 8 node numbers (4 bytes at least) and 3 coordinates of every
  // node (4 bytes at least): a header that states more than the file can hold is refused before allocating.
  if (h.kind != "netCDF-4") {
    const auto bytes = fs::file_size(path, ec);
    const double need = 32.0 * elements + 12.0 * nodes;
    if (!ec && need > static_cast<double>(bytes))
      fail(path, "the header states " + std::to_string(elements) + " elements and " + std::to_string(nodes) +
                     " nodes, which need at least " + std::to_string(static_cast<long long>(need)) + " bytes, but the file has " +
                     std::to_string(bytes) + ": a damaged, crafted or truncated file");
  }
  // The stated limits (mesh/README.md): 8 x elements and 3 x nodes index int arrays.
  if (elements > kMaxElements || nodes > kMaxNodes)
    fail(path, "the header states " + std::to_string(elements) + " elements and " + std::to_string(nodes) +
                   " nodes; tribex reads at most " + std::to_string(kMaxElements) + " elements and " +
                   std::to_string(kMaxNodes) + " nodes from one file (split the model, or check the file)");
  h.per_metre = exodus::length_unit_of(exo, path).per_metre;
  read_blocks(exo, path, nblocks, h);
  h.id = f.id;
  f.id = -1;  // the caller closes it
  return h;
}

exodus::SetOutline exodus::set_outline(int exo, const Header& h, bool side_sets, const std::string& path) {
  const ex_entity_type type = side_sets ? EX_SIDE_SET : EX_NODE_SET;
  SetOutline o;
  o.ids = entity_ids(exo, type, side_sets ? h.side_sets : h.node_sets, path, side_sets ? "side set" : "node set");
  const auto names = entity_names(exo, type, o.ids.size(), h.name_length);
  std::set<std::string> seen;
  for (std::size_t s = 0; s < o.ids.size(); ++s) {
    const std::string name = !names[s].empty() ? names[s]
                             : (side_sets ? "surface_" : "nodelist_") + std::to_string(o.ids[s]);
    const std::string what = std::string(side_sets ? "side set '" : "node set '") + name + "'";
    int count = 0, factors = 0;
    if (ex_get_set_param(exo, type, o.ids[s], &count, &factors) < 0 || count < 0) fail(path, "cannot read " + what + reason());
    if (!seen.insert(name).second)
      fail(path, std::string("two ") + (side_sets ? "side" : "node") + " sets are named '" + name + "'; rename one of them");
    o.names.push_back(name);
    o.entries.push_back(count);
  }
  return o;
}

Mesh read_exodus(const std::string& path) {
  exodus::Header h = exodus::open_checked(path);
  ExoFile f;
  f.id = h.id;
  const int exo = f.id, nodes = h.nodes, elements = h.elements, name_length = h.name_length;
  Mesh m;
  {
    const double per_metre = h.per_metre;
    std::vector<double> x(static_cast<std::size_t>(nodes)), y(x.size()), z(x.size());
    if (ex_get_coord(exo, x.data(), y.data(), z.data()) < 0) fail(path, "cannot read the coordinates" + reason());
    m.coordinates.resize(3 * x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      m.coordinates[3 * i] = per_metre == 1.0 ? x[i] : x[i] / per_metre;
      m.coordinates[3 * i + 1] = per_metre == 1.0 ? y[i] : y[i] / per_metre;
      m.coordinates[3 * i + 2] = per_metre == 1.0 ? z[i] : z[i] / per_metre;
    }
  }
  // Element blocks, in file order: Exodus numbers elements block after block, and connectivity
  // and side sets use that internal numbering (1-based positions), never the element id map.
  m.connectivity.resize(8 * static_cast<std::size_t>(elements));
  for (std::size_t b = 0; b < h.blocks.size(); ++b) {
    const Block& blk = h.blocks[b];
    if (ex_get_conn(exo, EX_ELEM_BLOCK, h.block_ids[b], m.connectivity.data() + 8 * static_cast<std::size_t>(blk.first_element),
                    nullptr, nullptr) < 0)
      fail(path, "cannot read the connectivity of block '" + blk.name + "'" + reason());
  }
  m.blocks = h.blocks;

  // Nodes no hex uses are dropped (they would carry no mass); the others keep their file order.
  std::vector<int> renumber(static_cast<std::size_t>(nodes), -1);
  for (int& n : m.connectivity) {
    if (n < 1 || n > nodes)
      fail(path, "an element refers to node " + std::to_string(n) + ", outside 1.." + std::to_string(nodes));
    renumber[static_cast<std::size_t>(n - 1)] = 0;
    n -= 1;
  }
  int used = 0;
  for (int& r : renumber)
    if (r == 0) r = used++;
  if (used < nodes) {
    std::vector<double> kept(3 * static_cast<std::size_t>(used));
    for (std::size_t i = 0; i < renumber.size(); ++i)
      if (renumber[i] >= 0) std::copy_n(m.coordinates.begin() + 3 * i, 3, kept.begin() + 3 * renumber[i]);
    m.coordinates = std::move(kept);
    for (int& n : m.connectivity) n = renumber[static_cast<std::size_t>(n)];
  }

  const std::vector<int> nset_ids = entity_ids(exo, EX_NODE_SET, h.node_sets, path, "node set");
  const auto nset_names = entity_names(exo, EX_NODE_SET, nset_ids.size(), name_length);
  for (std::size_t s = 0; s < nset_ids.size(); ++s) {
    const std::string name = nset_names[s].empty() ? "nodelist_" + std::to_string(nset_ids[s]) : nset_names[s];
    const std::vector<int> list = set_entries(exo, EX_NODE_SET, nset_ids[s], path, "node set '" + name + "'").first;
    std::vector<int> set;
    for (int n : list) {
      if (n < 1 || n > nodes)
        fail(path, "node set '" + name + "' refers to node " + std::to_string(n) + ", outside 1.." + std::to_string(nodes));
      if (renumber[static_cast<std::size_t>(n - 1)] >= 0) set.push_back(renumber[static_cast<std::size_t>(n - 1)]);
    }
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
    if (!m.node_sets.emplace(name, std::move(set)).second)
      fail(path, "two node sets are named '" + name + "'; rename one of them");
  }

  const std::vector<int> sset_ids = entity_ids(exo, EX_SIDE_SET, h.side_sets, path, "side set");
  const auto sset_names = entity_names(exo, EX_SIDE_SET, sset_ids.size(), name_length);
  for (std::size_t s = 0; s < sset_ids.size(); ++s) {
    const std::string name = sset_names[s].empty() ? "surface_" + std::to_string(sset_ids[s]) : sset_names[s];
    const auto [elems, sides] = set_entries(exo, EX_SIDE_SET, sset_ids[s], path, "side set '" + name + "'");
    std::vector<Side> set;
    for (std::size_t k = 0; k < elems.size(); ++k) {
      if (elems[k] < 1 || elems[k] > elements || sides[k] < 1 || sides[k] > 6)
        fail(path, "side set '" + name + "' has (element " + std::to_string(elems[k]) + ", side " +
                       std::to_string(sides[k]) + "), outside elements 1.." + std::to_string(elements) +
                       " and HEX8 sides 1..6");
      set.push_back({elems[k] - 1, sides[k] - 1});
    }
    if (!m.side_sets.emplace(name, std::move(set)).second)
      fail(path, "two side sets are named '" + name + "'; rename one of them");
  }

  // Element numbers in validate's messages are positions in the file; say so when the file's
  // element id map would name them otherwise.
  std::vector<int> map(static_cast<std::size_t>(elements));
  bool identity = ex_get_id_map(exo, EX_ELEM_MAP, map.data()) < 0;
  if (!identity) {
    identity = true;
    for (std::size_t i = 0; i < map.size() && identity; ++i) identity = map[i] == static_cast<int>(i + 1);
  }
  try {
    validate(m, path);
  } catch (const MeshError& e) {
    if (identity) throw;
    throw MeshError(std::string(e.what()) + " (element numbers are positions in the file, not its element ids)");
  }
  // As from gmsh (mesh/README.md): a side set's nodes are also a node set of its name unless the file
  // has one, so that a Cubit mesh with side sets only can be held by `fixed displacement` there.
  for (const auto& [name, sides] : m.side_sets)
    if (!m.node_sets.count(name)) m.node_sets[name] = m.side_set_nodes(name);
  return m;
}

int exodus::create_with_mesh(const Mesh& mesh, const std::string& path, const std::string& title, ExodusFormat format,
                             const ExodusLengthUnit& unit, const std::vector<std::string>& notes,
                             bool keep_empty_blocks, std::size_t name_length) {
  validate(mesh, "mesh for " + path);
  quiet_exodus();
  int comp_ws = sizeof(double), io_ws = sizeof(double);
  const int mode = EX_CLOBBER | EX_LARGE_MODEL | (format == ExodusFormat::netcdf4 ? EX_NETCDF4 : 0);
  ExoFile f;
  f.id = ex_create(path.c_str(), mode, &comp_ws, &io_ws);
  if (f.id < 0) fail(path, "cannot create the Exodus II file" + reason() + "; check the folder exists and is writable");
  const int exo = f.id;
  const auto check = [&](int status, const std::string& what) {
    if (status < 0) fail(path, "cannot write " + what + reason());
  };

  // Blocks in element order, so that Exodus's block-after-block element numbering is tribex's.
  std::vector<const Block*> blocks;
  for (const auto& b : mesh.blocks)
    if (b.element_count > 0 || keep_empty_blocks) blocks.push_back(&b);
  // Stable: empty blocks (keep_empty_blocks) share their first_element with the next one and keep the caller's order.
  std::stable_sort(blocks.begin(), blocks.end(),
                   [](const Block* a, const Block* b) { return a->first_element < b->first_element; });
  std::size_t longest = std::max<std::size_t>(32, name_length);
  for (const auto* b : blocks) longest = std::max(longest, b->name.size());
  for (const auto& [n, s] : mesh.node_sets) longest = std::max(longest, n.size());
  for (const auto& [n, s] : mesh.side_sets) longest = std::max(longest, n.size());
  if (longest > 255) fail(path, "a block or set name is longer than 255 characters, Exodus II's limit; shorten it");
  check(ex_set_max_name_length(exo, static_cast<int>(longest)), "the name length");

  const int n = mesh.node_count(), e = mesh.element_count();
  check(ex_put_init(exo, title.substr(0, MAX_LINE_LENGTH).c_str(), 3, n, e, static_cast<int>(blocks.size()),
                    static_cast<int>(mesh.node_sets.size()), static_cast<int>(mesh.side_sets.size())),
        "the header");
  {
    std::vector<double> x(static_cast<std::size_t>(n)), y(x.size()), z(x.size());
    const double s = unit.per_metre;  // 1: the values as they are
    for (std::size_t i = 0; i < x.size(); ++i) {
      x[i] = s == 1.0 ? mesh.coordinates[3 * i] : mesh.coordinates[3 * i] * s;
      y[i] = s == 1.0 ? mesh.coordinates[3 * i + 1] : mesh.coordinates[3 * i + 1] * s;
      z[i] = s == 1.0 ? mesh.coordinates[3 * i + 2] : mesh.coordinates[3 * i + 2] * s;
    }
    check(ex_put_coord(exo, x.data(), y.data(), z.data()), "the coordinates");
    const char* axes[3] = {"x", "y", "z"};
    check(ex_put_coord_names(exo, const_cast<char**>(axes)), "the coordinate names");
  }
  if (!notes.empty() || unit.name != "m" || unit.per_metre != 1.0) {
    // Info records: the unit first (the one read_exodus looks for), then the caller's lines.
    std::vector<std::string> lines{exodus_length_unit_record + unit.name};
    for (const auto& note : notes) lines.push_back(note.substr(0, MAX_LINE_LENGTH));
    std::vector<char*> p;
    for (auto& l : lines) p.push_back(l.data());
    check(ex_put_info(exo, static_cast<int>(lines.size()), p.data()), "the info records");
  }
  std::vector<std::string> names;
  std::vector<int> one_based;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const Block& blk = *blocks[b];
    check(ex_put_block(exo, EX_ELEM_BLOCK, static_cast<ex_entity_id>(b + 1), "HEX8", blk.element_count, 8, 0, 0, 0),
          "block '" + blk.name + "'");
    if (blk.element_count == 0) {
      names.push_back(blk.name);
      continue;
    }
    const auto first = mesh.connectivity.begin() + 8 * static_cast<std::ptrdiff_t>(blk.first_element);
    one_based.assign(first, first + 8 * static_cast<std::ptrdiff_t>(blk.element_count));
    for (int& v : one_based) ++v;
    check(ex_put_conn(exo, EX_ELEM_BLOCK, static_cast<ex_entity_id>(b + 1), one_based.data(), nullptr, nullptr),
          "the connectivity of block '" + blk.name + "'");
    names.push_back(blk.name);
  }
  check(put_names(exo, EX_ELEM_BLOCK, names), "the block names");

  names.clear();
  int id = 0;
  for (const auto& [name, nodes] : mesh.node_sets) {
    ++id;
    check(ex_put_set_param(exo, EX_NODE_SET, id, static_cast<int64_t>(nodes.size()), 0), "node set '" + name + "'");
    one_based.assign(nodes.begin(), nodes.end());
    for (int& v : one_based) ++v;
    if (!nodes.empty()) check(ex_put_set(exo, EX_NODE_SET, id, one_based.data(), nullptr), "node set '" + name + "'");
    names.push_back(name);
  }
  check(put_names(exo, EX_NODE_SET, names), "the node set names");

  names.clear();
  id = 0;
  std::vector<int> sides;
  for (const auto& [name, set] : mesh.side_sets) {
    ++id;
    check(ex_put_set_param(exo, EX_SIDE_SET, id, static_cast<int64_t>(set.size()), 0), "side set '" + name + "'");
    one_based.clear();
    sides.clear();
    for (const Side& s : set) {
      one_based.push_back(s.element + 1);
      sides.push_back(s.face + 1);  // Exodus sides 1..6 (mesh.hpp hex8_face_nodes)
    }
    if (!set.empty()) check(ex_put_set(exo, EX_SIDE_SET, id, one_based.data(), sides.data()), "side set '" + name + "'");
    names.push_back(name);
  }
  check(put_names(exo, EX_SIDE_SET, names), "the side set names");
  check(ex_update(exo), "the file to disk");
  const int result = f.id;
  f.id = -1;  // the caller owns it now
  return result;
}

void write_exodus(const Mesh& mesh, const std::string& path, ExodusFormat format) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::string hidden = ".";  // appended, not "." + name: GCC 12 warns (-Wrestrict) on that form
  hidden += target.filename().string();
  hidden += ".partial";
  const fs::path partial = target.parent_path() / hidden;
  require_output_target(path);  // only a regular file is replaced (a FIFO, device or folder: exit 2)
  require_output_target(partial.string());
  {
    ExoFile f;
    try {
      f.id = exodus::create_with_mesh(mesh, partial.string(), "tribex mesh", format);
    } catch (const MeshError& e) {
      std::error_code ec;
      fs::remove(partial, ec);
      std::string what = e.what();
      const std::string prefix = partial.string() + ": ";
      if (what.rfind(prefix, 0) == 0) what = path + ": " + what.substr(prefix.size());
      throw MeshError(what);
    }
    const int status = ex_close(f.id);
    f.id = -1;
    if (status < 0) {
      std::error_code ec;
      fs::remove(partial, ec);
      fail(path, "cannot close the Exodus II file" + reason());
    }
  }
  std::error_code ec;
  fs::rename(partial, target, ec);
  if (ec) {
    const std::string why = ec.message();  // before remove() reuses ec
    fs::remove(partial, ec);
    fail(path, "cannot rename the written file into place: " + why);
  }
}

}  // namespace tribex::mesh
