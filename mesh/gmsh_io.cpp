// SPDX-License-Identifier: MIT
// gmsh .msh read/write through the gmsh 4.8 API. See gmsh_io.hpp for the mapping and README.md for
// the rules. gmsh element types used: 5 = hex8, 3 = quad4, 15 = point.
#include "mesh/gmsh_io.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

#include "mesh/gmsh_session.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/msh_prescan.hpp"
#include "mesh/output_target.hpp"

namespace tribex::mesh {

namespace {

/// Groups the members of named sets by the sets that hold them: key = the names (sorted), value = the
/// members in no other combination. Every member appears under exactly one key.
template <class Member>
std::map<std::vector<std::string>, std::vector<Member>> shared_memberships(
    const std::map<std::string, std::vector<Member>>& sets) {
  std::map<Member, std::vector<std::string>> holders;
  for (const auto& [name, members] : sets)
    for (const Member& m : members) holders[m].push_back(name);  // names arrive sorted (std::map order)
  std::map<std::vector<std::string>, std::vector<Member>> groups;
  for (const auto& [member, names] : holders) groups[names].push_back(member);
  return groups;
}

constexpr int gmsh_hex8 = 5;
constexpr int gmsh_quad4 = 3;
constexpr int gmsh_point = 15;

/// gmsh 4.8 reports errors by throwing std::string (and also logs them). Run `body`; turn any gmsh
/// error into a one-line MeshError naming `path`.
template <class Body>
void call_gmsh(const std::string& path, const std::string& doing, const std::string& fix, Body&& body) {
  std::string what;
  try {
    body();
    return;
  } catch (const MeshError&) {
    throw;
  } catch (const std::string& s) {
    what = s;
  } catch (const std::exception& e) {
    what = e.what();
  }
  std::replace(what.begin(), what.end(), '\n', ' ');
  throw MeshError(path + ": gmsh failed while " + doing + " (" + what + "); " + fix);
}

/// First error gmsh logged since the logger was started, or "".
std::string first_logged_error() {
  std::vector<std::string> log;
  gmsh::logger::get(log);
  for (const std::string& line : log)
    if (line.rfind("Error", 0) == 0) return line;
  return "";
}

/// gmsh's name and node count of an element type; nullopt if gmsh does not know it (needs a live
/// GmshSession).
struct ElementProperties {
  std::string name;
  int nodes = 0;
};
std::optional<ElementProperties> element_properties(int type) {
  ElementProperties p;
  int dim = 0, order = 0, num_primary = 0;
  std::vector<double> local;
  try {
    gmsh::model::mesh::getElementProperties(type, p.name, dim, order, p.nodes, local, num_primary);
  } catch (...) {
    return std::nullopt;
  }
  return p;
}

std::string element_type_name(int type) {
  const auto p = element_properties(type);
  return p ? p->name : "type " + std::to_string(type);
}

/// Node count of a gmsh element type, 0 if gmsh does not know it (needs a live GmshSession).
int gmsh_nodes_per_element(int type) {
  const auto p = element_properties(type);
  return p ? p->nodes : 0;
}

/// gmsh node tag -> our 0-based node index (dense table when tags are dense, else a hash map).
class NodeIndex {
 public:
  explicit NodeIndex(const std::vector<std::size_t>& sorted_tags) {
    const std::size_t max_tag = sorted_tags.empty() ? 0 : sorted_tags.back();
    dense_ = max_tag <= 4 * sorted_tags.size() + 1024;
    if (dense_) {
      table_.assign(max_tag + 1, -1);
      for (std::size_t i = 0; i < sorted_tags.size(); ++i) table_[sorted_tags[i]] = static_cast<int>(i);
    } else {
      for (std::size_t i = 0; i < sorted_tags.size(); ++i) map_[sorted_tags[i]] = static_cast<int>(i);
    }
  }
  int operator()(std::size_t tag) const {
    if (dense_) return tag < table_.size() ? table_[tag] : -1;
    const auto it = map_.find(tag);
    return it == map_.end() ? -1 : it->second;
  }

 private:
  bool dense_ = true;
  std::vector<int> table_;
  std::unordered_map<std::size_t, int> map_;
};

struct PhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> entities;
};

std::vector<PhysicalGroup> physical_groups() {
  gmsh::vectorpair dim_tags;
  gmsh::model::getPhysicalGroups(dim_tags);
  std::vector<PhysicalGroup> groups;
  for (const auto& [dim, tag] : dim_tags) {
    PhysicalGroup g{dim, tag, "", {}};
    gmsh::model::getPhysicalName(dim, tag, g.name);
    if (g.name.empty())
      g.name = (dim == 3 ? "block_" : dim == 2 ? "surface_" : "nodes_") + std::to_string(tag);
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, g.entities);
    groups.push_back(std::move(g));
  }
  std::sort(groups.begin(), groups.end(),
            [](const PhysicalGroup& a, const PhysicalGroup& b) { return std::pair(a.dim, a.tag) < std::pair(b.dim, b.tag); });
  return groups;
}

void check_file_is_msh(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw MeshError(path + ": no such file; check the mesh file path");
  if (!std::filesystem::is_regular_file(path, ec))
    throw MeshError(path + ": not a regular file; give the path of a gmsh .msh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshError(path + ": cannot be opened for reading; check its permissions");
  std::string head(64, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const std::size_t start = head.find_first_not_of(" \t\r\n");
  if (start == std::string::npos || head.compare(start, 11, "$MeshFormat") != 0)
    throw MeshError(path + ":1: not a gmsh mesh file (byte " + std::to_string(start == std::string::npos ? 0 : start) +
                    ": expected '$MeshFormat'); export the mesh from gmsh as .msh (File > Export, format 4.1)");
}

/// Every face of every hex, keyed by its sorted node indices, for matching quads to hex faces.
struct FaceKey {
  std::array<int, 4> sorted;
  int element;
  int face;
};

std::vector<FaceKey> all_faces(const Mesh& mesh) {
  std::vector<FaceKey> faces;
  faces.reserve(static_cast<std::size_t>(mesh.element_count()) * 6);
  for (int e = 0; e < mesh.element_count(); ++e)
    for (int f = 0; f < 6; ++f) {
      std::array<int, 4> n = mesh.side_nodes({e, f});
      std::sort(n.begin(), n.end());
      faces.push_back({n, e, f});
    }
  std::sort(faces.begin(), faces.end(), [](const FaceKey& a, const FaceKey& b) { return a.sorted < b.sorted; });
  return faces;
}

/// True if `a` is a cyclic rotation of `b` (same orientation).
bool same_orientation(const std::array<int, 4>& a, const std::array<int, 4>& b) {
  for (int r = 0; r < 4; ++r) {
    bool equal = true;
    for (int k = 0; k < 4 && equal; ++k) equal = a[k] == b[(k + r) % 4];
    if (equal) return true;
  }
  return false;
}

// Step 1: the file's volume elements are hex8 and there are some.
void check_volume_types(const std::string& path) {
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 3, -1);
  for (int t : types)
    if (t != gmsh_hex8)
      throw MeshError(path + ": has volume elements of type '" + element_type_name(t) +
                      "'; tribex needs an all-hex8 mesh: in gmsh use transfinite volumes with Mesh.RecombineAll = 1 "
                      "(or Mesh.SubdivisionAlgorithm = 2) and Mesh.ElementOrder = 1");
  if (types.empty())
    throw MeshError(path + ": has no volume (3-D) elements; tribex needs a hex8 volume mesh (gmsh: Mesh > 3D)");
}

// A block's hexes as gmsh gives them, sorted by element tag.
struct RawBlock {
  std::string name;
  std::vector<std::pair<std::size_t, std::array<std::size_t, 8>>> elements;  // (gmsh tag, node tags)
};

// Step 2: blocks from the 3-D physical groups (or one block "block_1" when the file has none); a volume
// holding hexes in no physical volume is an error.
std::vector<RawBlock> raw_blocks(const std::string& path, const std::vector<PhysicalGroup>& groups) {
  std::vector<PhysicalGroup> volume_groups;
  for (const PhysicalGroup& g : groups)
    if (g.dim == 3) volume_groups.push_back(g);
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  if (volume_groups.empty()) {
    PhysicalGroup all{3, 1, "block_1", {}};
    for (const auto& dt : volumes) all.entities.push_back(dt.second);
    volume_groups.push_back(all);
  }
  std::vector<RawBlock> raw;
  std::set<int> entities_in_blocks;
  for (const PhysicalGroup& g : volume_groups) {
    RawBlock b{g.name, {}};
    for (int entity : g.entities) {
      entities_in_blocks.insert(entity);
      std::vector<std::size_t> tags, nodes;
      gmsh::model::mesh::getElementsByType(gmsh_hex8, tags, nodes, entity);
      for (std::size_t i = 0; i < tags.size(); ++i) {
        std::array<std::size_t, 8> n{};
        std::copy_n(nodes.begin() + static_cast<std::ptrdiff_t>(8 * i), 8, n.begin());
        b.elements.emplace_back(tags[i], n);
      }
    }
    std::sort(b.elements.begin(), b.elements.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    raw.push_back(std::move(b));
  }
  for (const auto& [dim, tag] : volumes) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(gmsh_hex8, tags, nodes, tag);
    if (!tags.empty() && !entities_in_blocks.count(tag))
      throw MeshError(path + ": volume " + std::to_string(tag) + " holds " + std::to_string(tags.size()) +
                      " hexes but is in no physical volume; add it to one (Physical Volume) so it becomes a block");
  }
  return raw;
}

// Step 3: the node tags the hexes use, sorted and unique (our node i is used[i]).
std::vector<std::size_t> used_node_tags(const std::string& path, const std::vector<RawBlock>& raw) {
  std::vector<std::size_t> used;
  for (const RawBlock& b : raw)
    for (const auto& el : b.elements) used.insert(used.end(), el.second.begin(), el.second.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  if (used.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 3))
    throw MeshError(path + ": too many nodes for int indices");
  return used;
}

// Step 3: the used nodes' coordinates, in our order; a used node without coordinates is an error.
void read_coordinates(const std::string& path, const std::vector<std::size_t>& used, const NodeIndex& index, Mesh& mesh) {
  mesh.coordinates.resize(used.size() * 3);
  std::vector<std::size_t> tags;
  std::vector<double> xyz, parametric;
  gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
  std::vector<char> seen(used.size(), 0);
  for (std::size_t i = 0; i < tags.size(); ++i) {
    const int n = index(tags[i]);
    if (n < 0) continue;
    std::copy_n(xyz.begin() + static_cast<std::ptrdiff_t>(3 * i), 3, mesh.coordinates.begin() + 3 * n);
    seen[n] = 1;
  }
  for (std::size_t n = 0; n < used.size(); ++n)
    if (!seen[n])
      throw MeshError(path + ": node tag " + std::to_string(used[n]) + " is used by a hex but has no coordinates; the file is incomplete");
}

// Step 4: the elements, block by block (blocks need contiguous element ranges); a hex in two blocks is an error.
void add_elements(const std::string& path, const std::vector<RawBlock>& raw, const NodeIndex& index, Mesh& mesh) {
  std::set<std::size_t> element_tags_seen;
  for (const RawBlock& b : raw) {
    Block block{b.name, mesh.element_count(), static_cast<int>(b.elements.size())};
    for (const auto& [tag, nodes] : b.elements) {
      if (!element_tags_seen.insert(tag).second)
        throw MeshError(path + ": hex element tag " + std::to_string(tag) + " is in two physical volumes ('" +
                        b.name + "' and another); every element must be in exactly one block");
      for (std::size_t n : nodes) mesh.connectivity.push_back(index(n));
    }
    mesh.blocks.push_back(block);
  }
}

// The sorted unique nodes of a non-volume physical group; a node on no hex is an error.
std::vector<int> group_nodes(const std::string& path, const PhysicalGroup& g, const NodeIndex& index) {
  std::vector<std::size_t> node_tags;
  std::vector<double> xyz;
  gmsh::model::mesh::getNodesForPhysicalGroup(g.dim, g.tag, node_tags, xyz);
  std::vector<int> nodes;
  for (std::size_t t : node_tags) {
    const int n = index(t);
    if (n < 0)
      throw MeshError(path + ": physical group '" + g.name + "' (dim " + std::to_string(g.dim) + ") has node tag " +
                      std::to_string(t) + " that belongs to no hex; sets must lie on the volume mesh");
    nodes.push_back(n);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

// The sides of a physical surface: each quad4 of its entities matched to a hex face (`faces`: all_faces).
std::vector<Side> surface_sides(const std::string& path, const PhysicalGroup& g, const NodeIndex& index,
                                const std::vector<FaceKey>& faces, const Mesh& mesh) {
  std::vector<Side> sides;
  for (int entity : g.entities) {
    std::vector<int> surface_types;
    gmsh::model::mesh::getElementTypes(surface_types, 2, entity);
    for (int t : surface_types)
      if (t != gmsh_quad4)
        throw MeshError(path + ": physical surface '" + g.name + "' holds elements of type '" + element_type_name(t) +
                        "'; side sets must be quad4 faces of the hex mesh (recombine the surface mesh)");
    std::vector<std::size_t> tags, quad_nodes;
    gmsh::model::mesh::getElementsByType(gmsh_quad4, tags, quad_nodes, entity);
    for (std::size_t q = 0; q < tags.size(); ++q) {
      std::array<int, 4> quad{};
      for (int k = 0; k < 4; ++k) quad[k] = index(quad_nodes[4 * q + k]);
      std::array<int, 4> key = quad;
      std::sort(key.begin(), key.end());
      const auto [lo, hi] = std::equal_range(faces.begin(), faces.end(), FaceKey{key, 0, 0},
                                             [](const FaceKey& a, const FaceKey& b) { return a.sorted < b.sorted; });
      if (key[0] < 0 || lo == hi)
        throw MeshError(path + ": quad element tag " + std::to_string(tags[q]) + " of physical surface '" + g.name +
                        "' is not a face of any hex; side sets must be faces of the volume mesh");
      // An interior face is shared by two hexes: take the one whose outward normal the quad's
      // node order gives (a boundary face has one candidate).
      auto pick = lo;
      for (auto it = lo; it != hi; ++it)
        if (same_orientation(quad, mesh.side_nodes({it->element, it->face}))) {
          pick = it;
          break;
        }
      sides.push_back({pick->element, pick->face});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return std::pair(a.element, a.face) < std::pair(b.element, b.face);
  });
  return sides;
}

// Step 5: side sets (2-D groups, quads matched to hex faces) and node sets (every non-volume group).
void add_sets(const std::string& path, const std::vector<PhysicalGroup>& groups, const NodeIndex& index, Mesh& mesh) {
  std::vector<FaceKey> faces;
  std::set<std::string> explicit_node_sets;  // from 0-D/1-D groups: they win over a 2-D group's nodes
  for (const PhysicalGroup& g : groups) {
    if (g.dim == 3) continue;
    std::vector<int> nodes = group_nodes(path, g, index);
    if (g.dim < 2) {
      if (!explicit_node_sets.insert(g.name).second)
        throw MeshError(path + ": two point/curve physical groups are named '" + g.name + "'; rename one");
      mesh.node_sets[g.name] = std::move(nodes);
      continue;
    }
    if (mesh.side_sets.count(g.name))
      throw MeshError(path + ": two physical surfaces are named '" + g.name + "'; rename one");
    if (!explicit_node_sets.count(g.name)) mesh.node_sets[g.name] = nodes;
    if (faces.empty()) faces = all_faces(mesh);
    mesh.side_sets[g.name] = surface_sides(path, g, index, faces, mesh);
  }
}

Mesh extract_mesh(const std::string& path) {
  const std::vector<PhysicalGroup> groups = physical_groups();
  check_volume_types(path);
  const std::vector<RawBlock> raw = raw_blocks(path, groups);
  const std::vector<std::size_t> used = used_node_tags(path, raw);
  const NodeIndex index(used);
  Mesh mesh;
  read_coordinates(path, used, index, mesh);
  add_elements(path, raw, index, mesh);
  add_sets(path, groups, index, mesh);
  return mesh;
}

}  // namespace

Mesh read_gmsh(const std::string& path) {
  check_file_is_msh(path);
  Mesh mesh;
  {
    GmshSession session;
    prescan_msh41(path, gmsh_nodes_per_element);  // gmsh 4.8 can crash on corrupt tags: check first
    GmshScratchModel model("read");
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(path, ec);
    const std::string fix = "the file (" + std::to_string(bytes) +
                            " bytes) is truncated or corrupt: write it again from gmsh (format 4.1 or 2.2)";
    call_gmsh(path, "reading it", fix, [&] {
      gmsh::logger::start();
      try {
        gmsh::merge(path);
      } catch (...) {
        gmsh::logger::stop();
        throw;
      }
      const std::string error = first_logged_error();
      gmsh::logger::stop();
      if (!error.empty()) throw MeshError(path + ": gmsh could not read it (" + error + "); " + fix);
      mesh = extract_mesh(path);
    });
  }
  validate(mesh, path);
  return mesh;
}

void write_gmsh(const Mesh& mesh, const std::string& path, bool binary, double version) {
  validate(mesh, "mesh to write to " + path);
  if (mesh.node_count() == 0) throw MeshError(path + ": refusing to write an empty mesh");
  const std::filesystem::path target(path);
  std::filesystem::path tmp = target;
  tmp.replace_filename("." + target.filename().string() + ".partial.msh");  // renamed at the end: never half-written
  require_output_target(path);  // only a regular file is replaced (a FIFO, device or folder: exit 2)
  require_output_target(tmp.string());

  GmshSession session;
  GmshScratchModel model("write");
  call_gmsh(path, "writing it", "check that the directory exists and is writable", [&] {
    const int nn = mesh.node_count();
    // Route 1 of docs/dependencies.md: discrete entities holding our mesh as it is. One volume per block,
    // one surface per side set, one point entity per extra node set.
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) gmsh::model::addDiscreteEntity(3, static_cast<int>(b) + 1);
    std::vector<std::size_t> node_tags(static_cast<std::size_t>(nn));
    for (int n = 0; n < nn; ++n) node_tags[n] = static_cast<std::size_t>(n) + 1;
    gmsh::model::mesh::addNodes(3, 1, node_tags, mesh.coordinates);

    std::size_t next_element_tag = 1;
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
      const Block& block = mesh.blocks[b];
      std::vector<std::size_t> tags(static_cast<std::size_t>(block.element_count));
      std::vector<std::size_t> conn(tags.size() * 8);
      for (int e = 0; e < block.element_count; ++e) {
        tags[e] = static_cast<std::size_t>(block.first_element + e) + 1;  // element e has tag e+1
        for (int a = 0; a < 8; ++a)
          conn[8 * e + a] = static_cast<std::size_t>(mesh.connectivity[8 * static_cast<std::size_t>(block.first_element + e) + a]) + 1;
      }
      gmsh::model::mesh::addElementsByType(static_cast<int>(b) + 1, gmsh_hex8, tags, conn);
      const int group = gmsh::model::addPhysicalGroup(3, {static_cast<int>(b) + 1}, static_cast<int>(b) + 1);
      gmsh::model::setPhysicalName(3, group, block.name);
    }
    next_element_tag = static_cast<std::size_t>(mesh.element_count()) + 1;
    std::map<std::string, std::vector<int>> surfaces_of, points_of;  // set name -> its gmsh entities

    // gmsh holds each element once: a face in several side sets (substrate_track inside substrate_top,
    // substrate_xmin inside substrate_sides) goes into one surface entity per combination of sets, and
    // each set's physical group names the entities it covers, so `gmsh -check` finds no duplicates.
    // The same for the points of the extra node sets.
    int surface = 0;
    for (const auto& [names, sides] : shared_memberships(mesh.side_sets)) {
      gmsh::model::addDiscreteEntity(2, ++surface);
      std::vector<std::size_t> tags(sides.size()), conn(sides.size() * 4);
      for (std::size_t s = 0; s < sides.size(); ++s) {
        tags[s] = next_element_tag++;
        const std::array<int, 4> n = mesh.side_nodes(sides[s]);  // counter-clockwise from outside
        for (int k = 0; k < 4; ++k) conn[4 * s + k] = static_cast<std::size_t>(n[k]) + 1;
      }
      gmsh::model::mesh::addElementsByType(surface, gmsh_quad4, tags, conn);
      for (const std::string& name : names) surfaces_of[name].push_back(surface);
    }
    for (const auto& [name, sides] : mesh.side_sets)
      if (!surfaces_of.count(name)) {  // an empty set keeps its name on an empty entity
        gmsh::model::addDiscreteEntity(2, ++surface);
        surfaces_of[name].push_back(surface);
      }
    for (const auto& [name, entities] : surfaces_of)
      gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, entities), name);

    std::map<std::string, std::vector<int>> extra_node_sets;
    for (const auto& [name, nodes] : mesh.node_sets)
      if (!mesh.side_sets.count(name) || mesh.side_set_nodes(name) != nodes) extra_node_sets[name] = nodes;  // else rebuilt from the side set
    int point = 0;
    for (const auto& [names, nodes] : shared_memberships(extra_node_sets)) {
      gmsh::model::addDiscreteEntity(0, ++point);
      std::vector<std::size_t> tags(nodes.size()), conn(nodes.size());
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        tags[i] = next_element_tag++;
        conn[i] = static_cast<std::size_t>(nodes[i]) + 1;
      }
      gmsh::model::mesh::addElementsByType(point, gmsh_point, tags, conn);
      for (const std::string& name : names) points_of[name].push_back(point);
    }
    for (const auto& [name, nodes] : extra_node_sets)
      if (!points_of.count(name)) {
        gmsh::model::addDiscreteEntity(0, ++point);
        points_of[name].push_back(point);
      }
    for (const auto& [name, entities] : points_of)
      gmsh::model::setPhysicalName(0, gmsh::model::addPhysicalGroup(0, entities), name);

    gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
    gmsh::option::setNumber("Mesh.MshFileVersion", version);
    gmsh::option::setNumber("Mesh.SaveAll", 0);
    gmsh::logger::start();
    gmsh::write(tmp.string());
    const std::string error = first_logged_error();
    gmsh::logger::stop();
    std::error_code ec;
    if (!error.empty()) {
      std::filesystem::remove(tmp, ec);
      throw MeshError(path + ": gmsh could not write it (" + error + "); check the directory exists and is writable");
    }
    if (!std::filesystem::exists(tmp, ec))
      throw MeshError(path + ": gmsh wrote nothing; check the directory exists and is writable");
    std::filesystem::rename(tmp, target, ec);
    if (ec) {
      const std::string why = ec.message();  // before remove() reuses ec (it said "Success")
      std::filesystem::remove(tmp, ec);
      throw MeshError(path + ": cannot move the written mesh into place (" + why + ")");
    }
  });
}

}  // namespace tribex::mesh
