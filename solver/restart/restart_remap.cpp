// SPDX-License-Identifier: MIT
// remap_restart and the reading of the groups a rank needs (restart_remap.hpp). Lookups go through the
// rank's own sorted global numbers (binary search), so a rank holds its own arrays and one writer's group
// at a time besides them, never a whole-mesh map.
#include "solver/restart/restart_remap.hpp"

#include <algorithm>
#include <set>

#include "solver/element_block.hpp"

namespace tribex::solver {
namespace {

constexpr const char* kIds[] = {"global_node", "global_element", "block_ranges"};

bool is_id(const std::string& name) {
  return std::any_of(std::begin(kIds), std::end(kIds), [&](const char* id) { return name == id; });
}

struct Source {
  int group = -1;  // writer rank
  int index = -1;  // its local node or element
};

/// [i] the lowest writer holding wanted[i] (ascending, unique) in its `ids` array, and its local index there.
std::vector<Source> lowest_holders(const std::vector<int>& wanted, const std::vector<StateArchive>& groups,
                                   const char* ids) {
  std::vector<Source> out(wanted.size());
  for (int g = 0; g < static_cast<int>(groups.size()); ++g) {
    const auto& held = groups[static_cast<std::size_t>(g)].integer_array(ids);
    for (std::size_t i = 0; i < held.size(); ++i) {
      const auto it = std::lower_bound(wanted.begin(), wanted.end(), held[i]);
      if (it == wanted.end() || *it != held[i]) continue;
      Source& s = out[static_cast<std::size_t>(it - wanted.begin())];
      if (s.group < 0) s = {g, static_cast<int>(i)};
    }
  }
  return out;
}

std::vector<int> sorted_unique(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

/// The sources of this rank's nodes ([local node]) and contact rows ([row]): their owners.
struct NodeSources {
  std::vector<Source> node, contact_row;
};

NodeSources node_sources(const std::vector<StateArchive>& groups, const RestartLayout& layout) {
  std::vector<int> wanted = layout.global_node;
  wanted.insert(wanted.end(), layout.contact_global_node.begin(), layout.contact_global_node.end());
  wanted = sorted_unique(std::move(wanted));
  const auto holders = lowest_holders(wanted, groups, "global_node");
  const auto find = [&](int global) {
    const auto it = std::lower_bound(wanted.begin(), wanted.end(), global);
    const Source s = holders[static_cast<std::size_t>(it - wanted.begin())];
    if (s.group < 0)
      throw SetupError("the restart file holds no node " + std::to_string(global + 1) +
                       " (written for another mesh?); restart with the deck and mesh of the run that wrote it");
    return s;
  };
  NodeSources out;
  for (int g : layout.global_node) out.node.push_back(find(g));
  for (int g : layout.contact_global_node) out.contact_row.push_back(find(g));
  return out;
}

/// [local element] the writer that held it and its local element there.
std::vector<Source> element_sources(const std::vector<StateArchive>& groups, const RestartLayout& layout) {
  const std::vector<int> wanted = sorted_unique(layout.global_element);
  const auto holders = lowest_holders(wanted, groups, "global_element");
  std::vector<Source> out;
  out.reserve(layout.global_element.size());
  for (int g : layout.global_element) {
    const Source s = holders[static_cast<std::size_t>(std::lower_bound(wanted.begin(), wanted.end(), g) - wanted.begin())];
    if (s.group < 0)
      throw SetupError("the restart file holds no element " + std::to_string(g + 1) +
                       " (written for another mesh?); restart with the deck and mesh of the run that wrote it");
    out.push_back(s);
  }
  return out;
}

const std::vector<double>& sized(const StateArchive& a, const std::string& name, std::size_t rows, int& width) {
  const auto& v = a.array(name);
  if (rows == 0 || v.size() % rows != 0)
    throw SetupError("restart file: '" + name + "' has " + std::to_string(v.size()) + " values, not a whole number per row of " +
                     std::to_string(rows) + " (an edited or damaged restart file?)");
  width = static_cast<int>(v.size() / rows);
  return v;
}

void remap_node_fields(const std::vector<StateArchive>& groups, const RestartLayout& layout, const NodeSources& src,
                       StateArchive& out) {
  for (const std::string& name : layout.node_fields) {
    if (!groups[0].has(name)) continue;
    std::vector<const std::vector<double>*> from(groups.size(), nullptr);  // each writer's array, checked once
    std::vector<double> dest(3 * layout.global_node.size());
    for (std::size_t l = 0; l < src.node.size(); ++l) {
      const auto g = static_cast<std::size_t>(src.node[l].group);
      if (!from[g]) {
        int width = 0;
        from[g] = &sized(groups[g], name, groups[g].integer_array("global_node").size(), width);
        if (width != 3) throw SetupError("restart file: '" + name + "' is not 3 values per node");
      }
      for (int i = 0; i < 3; ++i) dest[3 * l + i] = (*from[g])[3 * static_cast<std::size_t>(src.node[l].index) + i];
    }
    out.put(name, dest);
  }
  for (const std::string& name : layout.reformed_node_fields)
    if (groups[0].has(name)) out.put(name, std::vector<double>(3 * layout.global_node.size(), 0.0));
}

/// Value k of element e of a block array with `width` values per element, plain or interleaved.
std::size_t record_index(int e, int k, int width, bool interleaved) {
  return interleaved ? lane_index(e, k, width) : static_cast<std::size_t>(width) * e + k;
}

/// The block of writer `group` holding its local element `e`, and e's index in it.
std::pair<int, int> writer_block(const StateArchive& a, int e) {
  const auto& ranges = a.integer_array("block_ranges");  // [block] first, count
  for (std::size_t b = 0; 2 * b + 1 < ranges.size(); ++b)
    if (e >= ranges[2 * b] && e < ranges[2 * b] + ranges[2 * b + 1]) return {static_cast<int>(b), e - static_cast<int>(ranges[2 * b])};
  throw SetupError("restart file: element in no block of 'block_ranges' (an edited or damaged restart file?)");
}

void remap_block_fields(const std::vector<StateArchive>& groups, const RestartLayout& layout,
                        const std::vector<Source>& src, StateArchive& out) {
  for (std::size_t b = 0; b < layout.blocks.size(); ++b) {
    const RestartLayout::Block& blk = layout.blocks[b];
    const std::string prefix = "block_" + std::to_string(b);
    struct Kind {
      std::string name;
      int width;
      bool interleaved;
    };
    std::vector<Kind> kinds{{prefix + "_stress", 6, false}};
    if (blk.state_width > 0) kinds.push_back({prefix + "_state", blk.state_width, blk.state_interleaved});
    for (const Kind& kind : kinds) {
      std::vector<double> dest(kind.interleaved ? interleaved_size(blk.count, kind.width)
                                                : static_cast<std::size_t>(kind.width) * blk.count, 0.0);
      for (int j = 0; j < blk.count; ++j) {
        const Source s = src[static_cast<std::size_t>(blk.first_element + j)];
        const StateArchive& a = groups[static_cast<std::size_t>(s.group)];
        const auto [wb, wj] = writer_block(a, s.index);
        if (wb != static_cast<int>(b))
          throw SetupError("restart file: an element of block " + std::to_string(b + 1) + " was written in block " +
                           std::to_string(wb + 1) + "; restart with the deck and mesh of the run that wrote it");
        const auto& v = a.array(kind.name);
        for (int k = 0; k < kind.width; ++k) {
          const std::size_t from = record_index(wj, k, kind.width, kind.interleaved);
          if (from >= v.size()) throw SetupError("restart file: '" + kind.name + "' is shorter than its block");
          dest[record_index(j, k, kind.width, kind.interleaved)] = v[from];
        }
      }
      out.put(kind.name, dest);
    }
  }
}

/// Copies row `row` (width values) of `name` in writer `g`'s archive into dest row `to`.
template <class T>
void copy_row(const std::vector<T>& from, std::size_t row, std::size_t to, int width, std::vector<T>& dest) {
  for (int i = 0; i < width; ++i) dest[to * width + i] = from.at(row * width + i);
}

// Pass p's candidate lists of the last search, each slave node's from its owner (the rank that searched
// for it), and the positions at that search by node; `searched` as written (searches are global steps).
void move_candidates(const std::vector<StateArchive>& groups, const RestartLayout& layout, const NodeSources& src,
                     std::size_t p, StateArchive& out) {
  const std::string q = "contact_pass_" + std::to_string(p) + "_";
  const auto& slaves = layout.pass_slave_rows[p];
  std::vector<long long> offset{0}, candidates;
  for (std::size_t j = 0; j < slaves.size(); ++j) {
    const StateArchive& a = groups[static_cast<std::size_t>(src.contact_row[static_cast<std::size_t>(slaves[j])].group)];
    const auto& from_offset = a.integer_array(q + "candidate_offset");
    const auto& from = a.integer_array(q + "candidates");
    if (from_offset.size() != slaves.size() + 1 || from_offset.at(j) < 0 || from_offset.at(j) > from_offset.at(j + 1) ||
        static_cast<std::size_t>(from_offset.at(j + 1)) > from.size())
      throw SetupError("restart file: '" + q + "candidate_offset' does not fit the pass's " +
                       std::to_string(slaves.size()) + " slave nodes (an edited or damaged restart file?)");
    candidates.insert(candidates.end(), from.begin() + from_offset[j], from.begin() + from_offset[j + 1]);
    offset.push_back(static_cast<long long>(candidates.size()));
  }
  out.put_integers(q + "candidate_offset", offset);
  out.put_integers(q + "candidates", candidates);
  out.put_integers(q + "searched", groups[0].integer_array(q + "searched"));
  const auto& rows = layout.pass_search_rows.at(p);
  std::vector<double> x(3 * rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r)
    copy_row(groups[static_cast<std::size_t>(src.contact_row[static_cast<std::size_t>(rows[r])].group)].array(q + "x_at_search"), r, r, 3, x);
  out.put(q + "x_at_search", x);
  out.put_integer("contact_candidates_moved", 1);
}

void remap_contact(const std::vector<StateArchive>& groups, const RestartLayout& layout, const NodeSources& src,
                   StateArchive& out) {
  const StateArchive& first = groups[0];
  if (!first.has("contact_passes")) return;
  const std::size_t rows = layout.contact_global_node.size();
  for (const std::string& name : layout.contact_row_fields) {
    int width = 0;
    sized(first, name, rows, width);
    std::vector<double> dest(rows * static_cast<std::size_t>(width));
    for (std::size_t k = 0; k < rows; ++k) copy_row(groups[static_cast<std::size_t>(src.contact_row[k].group)].array(name), k, k, width, dest);
    out.put(name, dest);
  }
  const auto passes = static_cast<std::size_t>(first.integer("contact_passes"));
  if (passes != layout.pass_slave_rows.size())
    throw SetupError("restart file has " + std::to_string(passes) + " contact passes, the deck " +
                     std::to_string(layout.pass_slave_rows.size()) + "; restart with the deck of the run that wrote it");
  for (std::size_t p = 0; p < passes; ++p) {
    const std::string q = "contact_pass_" + std::to_string(p) + "_";
    const auto& slaves = layout.pass_slave_rows[p];
    if (layout.keep_candidates) {
      move_candidates(groups, layout, src, p, out);
    } else {
      // Every pass searches at the first step: no candidates yet (a rank's lists are its region's).
      out.put_integers(q + "candidate_offset", std::vector<long long>(slaves.size() + 1, 0));
      out.put_integers(q + "candidates", {});
      out.put_integer(q + "searched", 0);
      out.put(q + "x_at_search", first.array(q + "x_at_search"));
    }
    out.put(q + "stable_dt", first.array(q + "stable_dt"));
    std::vector<double> gap(slaves.size());
    std::vector<long long> last_face(slaves.size());
    int width = 0;
    const bool has_law = first.has(q + "law_state");
    if (has_law) sized(first, q + "law_state", slaves.size(), width);
    std::vector<double> law(slaves.size() * static_cast<std::size_t>(width));
    for (std::size_t j = 0; j < slaves.size(); ++j) {
      const StateArchive& a = groups[static_cast<std::size_t>(src.contact_row[static_cast<std::size_t>(slaves[j])].group)];
      copy_row(a.array(q + "gap"), j, j, 1, gap);
      copy_row(a.integer_array(q + "last_face"), j, j, 1, last_face);
      if (has_law) copy_row(a.array(q + "law_state"), j, j, width, law);
    }
    out.put(q + "gap", gap);
    out.put_integers(q + "last_face", last_face);
    if (has_law) out.put(q + "law_state", law);
  }
}

bool remapped_elsewhere(const std::string& name, const RestartLayout& layout) {
  const auto in = [&](const std::vector<std::string>& v) { return std::find(v.begin(), v.end(), name) != v.end(); };
  return is_id(name) || in(layout.node_fields) || in(layout.reformed_node_fields) || in(layout.contact_row_fields) ||
         name.rfind("block_", 0) == 0 || name.rfind("contact_pass_", 0) == 0 || name == "contact_region";
}

}  // namespace

std::vector<char> needs_group(const std::vector<StateArchive>& ids, const RestartLayout& layout) {
  std::vector<char> need(ids.size(), 0);
  if (!need.empty()) need[0] = 1;
  const NodeSources nodes = node_sources(ids, layout);
  for (const auto* list : {&nodes.node, &nodes.contact_row})
    for (const Source& s : *list) need[static_cast<std::size_t>(s.group)] = 1;
  for (const Source& s : element_sources(ids, layout)) need[static_cast<std::size_t>(s.group)] = 1;
  return need;
}

StateArchive remap_restart(const std::vector<StateArchive>& groups, const RestartLayout& layout, int rank) {
  if (groups.empty()) throw SetupError("restart file has no rank groups");
  StateArchive out;
  const StateArchive& first = groups[0];
  for (const auto& [name, v] : first.reals)
    if (!remapped_elsewhere(name, layout)) out.put(name, v);
  for (const auto& [name, v] : first.integers)
    if (!remapped_elsewhere(name, layout)) out.put_integers(name, v);
  const NodeSources nodes = node_sources(groups, layout);
  remap_node_fields(groups, layout, nodes, out);
  remap_block_fields(groups, layout, element_sources(groups, layout), out);
  remap_contact(groups, layout, nodes, out);
  // The next step's reductions sum every rank's part: the writers' total on rank 0, in writer order.
  for (const auto& [name, index] : layout.partial_sums) {
    if (!out.has(name)) continue;
    double total = 0.0;
    for (const StateArchive& g : groups) total += g.array(name).at(static_cast<std::size_t>(index));
    out.reals[name].at(static_cast<std::size_t>(index)) = rank == 0 ? total : 0.0;
  }
  out.put_integer("node_count", static_cast<long long>(layout.global_node.size()));
  out.put_integer("element_count", static_cast<long long>(layout.global_element.size()));
  out.put_integer("remapped_from_ranks", static_cast<long long>(groups.size()));
  return out;
}

StateArchive read_restart_for(const std::string& path, const RestartLayout& layout, int rank, int ranks,
                              bool always_remap) {
  const RestartFile file(path);
  if (file.ranks() == ranks && !always_remap) return file.read_group(rank);
  std::vector<StateArchive> groups(static_cast<std::size_t>(file.ranks()));
  for (int g = 0; g < file.ranks(); ++g) {
    groups[static_cast<std::size_t>(g)] = file.read_group(g, is_id);
    for (const char* id : kIds)
      if (!groups[static_cast<std::size_t>(g)].has(id))
        throw SetupError(path + ": error: the restart file was written by " + std::to_string(file.ranks()) +
                         " rank(s), this run has " + std::to_string(ranks) + ", and it keeps no global node and element "
                         "numbers (written by an earlier tribex) to move its state onto other ranks; restart with mpirun -np " +
                         std::to_string(file.ranks()) + " (tribex run --ranks " + std::to_string(file.ranks()) + ")");
  }
  const std::vector<char> need = needs_group(groups, layout);
  std::set<std::string> partial;
  for (const auto& p : layout.partial_sums) partial.insert(p.first);
  const auto is_partial = [&](const std::string& name) { return partial.count(name) > 0; };
  for (int g = 0; g < file.ranks(); ++g) {
    StateArchive& a = groups[static_cast<std::size_t>(g)];
    StateArchive more = need[static_cast<std::size_t>(g)] ? file.read_group(g) : file.read_group(g, is_partial);
    for (auto& [name, v] : more.reals) a.reals[name] = std::move(v);
    for (auto& [name, v] : more.integers) a.integers[name] = std::move(v);
  }
  return remap_restart(groups, layout, rank);
}

}  // namespace tribex::solver
