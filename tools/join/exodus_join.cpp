// SPDX-License-Identifier: MIT
// `tribex join` (exodus_join.hpp; README.md here).
#include "tools/join/exodus_join.hpp"

#include <exodusII.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <limits>
#include <optional>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <regex>
#include <set>
#include <vector>

#include "mesh/exodus_io.hpp"
#include "mesh/exodus_prescan.hpp"
#include "mesh/mesh_error.hpp"
#include "mesh/output_target.hpp"
#include "solver/output/exodus_rank_file.hpp"
#include "solver/output/output_manifest.hpp"
#include "tools/common/errors.hpp"

namespace tribex::join {
namespace {

namespace fs = std::filesystem;
using tools::BadInput;

struct RankFile;

// At most `most` rank files open at once, so that a join of N files needs no `ulimit -n` above N: opening
// one more closes the one opened longest ago. The join reads the files in rank order, so with N above the
// limit every read of a variable of a step reopens the files (N opens per variable per step; measured in
// README.md here); at or under it each file is opened once.
class OpenLimit {
 public:
  explicit OpenLimit(std::size_t most) : most_(std::max<std::size_t>(most, 1)) {}
  void opened(RankFile& f);
  void forget(const RankFile& f) { open_.erase(std::remove(open_.begin(), open_.end(), &f), open_.end()); }

 private:
  std::size_t most_;
  std::deque<RankFile*> open_;  // oldest first
};

// The descriptors a join may spend on rank files: the soft limit (`ulimit -n`) less 8 for the process's
// own (the standard streams, the joined file, the manifest, netCDF's and the C library's).
std::size_t rank_files_allowed() {
  rlimit limit{};
  if (getrlimit(RLIMIT_NOFILE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return 1024;
  return limit.rlim_cur > 9 ? static_cast<std::size_t>(limit.rlim_cur - 8) : 1;
}

// One rank's file, with what the join needs of its header; open for reading when `handle` is asked.
struct RankFile {
  std::string path;
  mutable int id = -1;  // the open file, or -1 (closed by OpenLimit; reopened by handle)
  OpenLimit* limit = nullptr;
  int nodes = 0, elements = 0;
  std::vector<int> node_map, element_map;  // [local] global index (0-based)
  std::vector<int> block_ids, block_counts, block_first;  // block_first: its first local element
  RankFile() = default;
  RankFile(const RankFile&) = delete;
  RankFile& operator=(const RankFile&) = delete;
  ~RankFile() {
    close();
    if (limit) limit->forget(*this);
  }
  void close() const {
    if (id >= 0) ex_close(id);
    id = -1;
  }
  // The open file's id; reopens it when the limit closed it (its header was checked at the first open).
  int handle() const {
    if (id >= 0) return id;
    int comp_ws = sizeof(double), io_ws = 0;
    float version = 0;
    id = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
    if (id < 0) fail("cannot open again");
    ex_set_max_name_length(id, static_cast<int>(ex_inquire_int(id, EX_INQ_DB_MAX_ALLOWED_NAME_LENGTH)));
    if (limit) limit->opened(const_cast<RankFile&>(*this));
    return id;
  }
  [[noreturn]] void fail(const std::string& what) const {
    const std::string e = mesh::exodus::last_error();
    throw BadInput(path + ": " + what + (e.empty() ? "" : " (" + e + ")") +
                   "; the rank file is incomplete or damaged: run again, or resume from a restart file");
  }
  void check(int status, const std::string& what) const {
    if (status < 0) fail("cannot read " + what);
  }
};

void OpenLimit::opened(RankFile& f) {
  while (open_.size() >= most_) {
    open_.front()->close();
    open_.pop_front();
  }
  open_.push_back(&f);
}

std::vector<std::string> names_of(int exo, ex_entity_type type, int count, const RankFile& f) {
  if (count <= 0) return {};
  const int length = std::max<int>(static_cast<int>(ex_inquire_int(exo, EX_INQ_DB_MAX_USED_NAME_LENGTH)), 32);
  std::vector<std::vector<char>> buffers(static_cast<std::size_t>(count), std::vector<char>(length + 1, '\0'));
  std::vector<char*> p;
  for (auto& b : buffers) p.push_back(b.data());
  f.check(ex_get_names(exo, type, p.data()), "the names");
  std::vector<std::string> names;
  for (auto& b : buffers) names.emplace_back(b.data());
  return names;
}

std::vector<std::string> variable_names(const RankFile& f, ex_entity_type type) {
  int count = 0;
  f.check(ex_get_variable_param(f.handle(), type, &count), "the variable counts");
  if (count <= 0) return {};
  const int length = std::max<int>(static_cast<int>(ex_inquire_int(f.handle(), EX_INQ_DB_MAX_USED_NAME_LENGTH)), 32);
  std::vector<std::vector<char>> buffers(static_cast<std::size_t>(count), std::vector<char>(length + 1, '\0'));
  std::vector<char*> p;
  for (auto& b : buffers) p.push_back(b.data());
  f.check(ex_get_variable_names(f.handle(), type, count, p.data()), "the variable names");
  std::vector<std::string> names;
  for (auto& b : buffers) names.emplace_back(b.data());
  return names;
}

// The rank counts N of the per-rank files OUT/results.exo.N.r there.
std::set<int> rank_counts_present(const std::string& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw BadInput(folder + ": not a folder; give the output folder of a parallel run (tribex join OUT)");
  const std::regex pattern(R"(results\.exo\.([0-9]+)\.([0-9]+))");
  std::set<int> counts;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, m, pattern) && m[1].length() < 7) counts.insert(std::stoi(m[1]));
  }
  if (counts.empty())
    throw BadInput(folder + ": no per-rank results files (results.exo.N.r); a parallel run with format = exodus "
                            "or both writes them");
  return counts;
}

void require_rank_files(const std::string& folder, int ranks) {
  std::error_code ec;
  for (int r = 0; r < ranks; ++r) {
    const fs::path p = fs::path(folder) / solver::output::rank_file_name(ranks, r);
    if (!fs::is_regular_file(p, ec))
      throw BadInput(p.string() + ": missing (rank " + std::to_string(r) + " of " + std::to_string(ranks) +
                     "); every rank's file is needed: run again, or resume from a restart file");
  }
}

// What to join: one rank count (`ranks`, or the only one there) from its first step to its last, or, when
// the folder holds several, the run's segments as its manifest records them (a run resumed on another rank
// count: solver/output/README.md "Restart on another rank count"), consecutive ones of one rank count merged.
// Segment k gives its rank count's steps with from_time(k) <= t < from_time(k + 1); the first has no lower bound.
std::vector<solver::RunSegment> segments_to_join(const std::string& folder, int ranks) {
  const double all = -std::numeric_limits<double>::infinity();
  const std::set<int> counts = rank_counts_present(folder);
  if (ranks <= 0 && counts.size() == 1) ranks = *counts.begin();
  if (ranks > 0) {
    require_rank_files(folder, ranks);
    return {{ranks, all}};
  }
  std::optional<solver::OutputManifest> manifest;
  try {
    manifest = solver::read_manifest(folder);
  } catch (const std::exception& e) {
    throw BadInput(e.what());
  }
  std::vector<solver::RunSegment> segments;
  std::set<int> listed;
  for (const auto& g : manifest ? manifest->segments : std::vector<solver::RunSegment>{}) {
    if (segments.empty() || segments.back().ranks != g.ranks) segments.push_back(g);
    listed.insert(g.ranks);
  }
  if (listed != counts)
    throw BadInput(folder + ": per-rank results files of " + std::to_string(counts.size()) +
                   " rank counts (results.exo.N.r with N = " + std::to_string(*counts.begin()) + ", " +
                   std::to_string(*counts.rbegin()) + ", ...) that the folder's manifest does not list as the segments "
                   "of its run; choose one with --ranks N");
  for (std::size_t k = 1; k < segments.size(); ++k)
    if (!(segments[k].from_time >= segments[k - 1].from_time))
      throw BadInput(folder + ": the manifest's run segments go back in time; choose one rank count with --ranks N");
  for (int n : counts) require_rank_files(folder, n);
  segments.front().from_time = all;
  return segments;
}

void open_rank(RankFile& f) {
  mesh::NetcdfHeader header;
  try {  // the header walk first: the library trusts the file's sizes (mesh/README.md)
    header = mesh::prescan_exodus_file(f.path);
  } catch (const mesh::MeshError& e) {
    throw BadInput(std::string(e.what()) + "; the rank file is incomplete or damaged: run again, or resume from a restart file");
  }
  // netCDF reads a record beyond the end of a cut file as fill values, silently: every step must be whole.
  if (header.file_size < header.records_end)
    f.fail("truncated: its steps need " + std::to_string(header.records_end) + " bytes, the file has " +
           std::to_string(header.file_size));
  int comp_ws = sizeof(double), io_ws = 0;
  float version = 0;
  ex_opts(EX_DEFAULT);
  f.id = ex_open(f.path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
  if (f.id < 0) f.fail("not a readable Exodus II file");
  if (f.limit) f.limit->opened(f);
  // The API cuts names it reads to 32 characters unless told the file's own limit (history columns are longer).
  ex_set_max_name_length(f.id, static_cast<int>(ex_inquire_int(f.id, EX_INQ_DB_MAX_ALLOWED_NAME_LENGTH)));
  char title[MAX_LINE_LENGTH + 1] = {};
  int dim = 0, blocks = 0, node_sets = 0, side_sets = 0;
  f.check(ex_get_init(f.id, title, &dim, &f.nodes, &f.elements, &blocks, &node_sets, &side_sets), "the header");
  f.node_map.resize(static_cast<std::size_t>(f.nodes));
  f.element_map.resize(static_cast<std::size_t>(f.elements));
  if (f.nodes > 0) f.check(ex_get_id_map(f.id, EX_NODE_MAP, f.node_map.data()), "the node number map");
  if (f.elements > 0) f.check(ex_get_id_map(f.id, EX_ELEM_MAP, f.element_map.data()), "the element number map");
  for (int& n : f.node_map) --n;
  for (int& e : f.element_map) --e;
  f.block_ids.resize(static_cast<std::size_t>(blocks));
  if (blocks > 0) f.check(ex_get_ids(f.id, EX_ELEM_BLOCK, f.block_ids.data()), "the block ids");
  int first = 0;
  for (int id : f.block_ids) {
    char type[MAX_STR_LENGTH + 1] = {};
    int count = 0, per = 0, edges = 0, faces = 0, attributes = 0;
    f.check(ex_get_block(f.id, EX_ELEM_BLOCK, id, type, &count, &per, &edges, &faces, &attributes), "a block");
    if (count > 0 && per != 8) f.fail("block " + std::to_string(id) + " is not HEX8");
    f.block_counts.push_back(count);
    f.block_first.push_back(first);
    first += count;
  }
}

// The whole mesh's blocks (names from rank 0, counts summed) and connectivity.
void join_blocks(const std::vector<std::unique_ptr<RankFile>>& files, mesh::Mesh& whole) {
  const RankFile& f0 = *files[0];
  const auto names = names_of(f0.handle(), EX_ELEM_BLOCK, static_cast<int>(f0.block_ids.size()), f0);
  int first = 0;
  for (std::size_t b = 0; b < f0.block_ids.size(); ++b) {
    int count = 0;
    for (const auto& f : files) {
      if (f->block_ids != f0.block_ids) f->fail("its blocks are not rank 0's");
      count += f->block_counts[b];
    }
    whole.blocks.push_back({names[b], first, count});
    first += count;
  }
  whole.connectivity.assign(8 * static_cast<std::size_t>(first), -1);
  std::vector<int> conn;
  for (const auto& f : files)
    for (std::size_t b = 0; b < f->block_ids.size(); ++b) {
      const int count = f->block_counts[b];
      if (count == 0) continue;
      conn.resize(8 * static_cast<std::size_t>(count));
      f->check(ex_get_conn(f->handle(), EX_ELEM_BLOCK, f->block_ids[b], conn.data(), nullptr, nullptr), "the connectivity");
      for (int i = 0; i < count; ++i) {
        const int e = f->element_map[static_cast<std::size_t>(f->block_first[b] + i)];
        const auto& blk = whole.blocks[b];
        if (e < blk.first_element || e >= blk.first_element + blk.element_count)
          f->fail("element " + std::to_string(e + 1) + " lies outside its block's global range");
        for (int k = 0; k < 8; ++k) {
          const int local = conn[8 * static_cast<std::size_t>(i) + k] - 1;
          if (local < 0 || local >= f->nodes) f->fail("a node number beyond the file's nodes");
          whole.connectivity[8 * static_cast<std::size_t>(e) + k] = f->node_map[static_cast<std::size_t>(local)];
        }
      }
    }
  if (std::find(whole.connectivity.begin(), whole.connectivity.end(), -1) != whole.connectivity.end())
    throw BadInput(f0.path + ": the rank files do not cover every element of the whole mesh; join the files of one run");
}

// The coordinates (as written: the files' length unit) and the node and side sets, in global numbers.
void join_nodes_and_sets(const std::vector<std::unique_ptr<RankFile>>& files, int global_nodes, mesh::Mesh& whole) {
  whole.coordinates.assign(3 * static_cast<std::size_t>(global_nodes), 0.0);
  std::vector<char> seen(static_cast<std::size_t>(global_nodes), 0);
  std::vector<double> x, y, z;
  for (const auto& f : files) {
    x.resize(static_cast<std::size_t>(f->nodes));
    y.resize(x.size());
    z.resize(x.size());
    if (f->nodes > 0) f->check(ex_get_coord(f->handle(), x.data(), y.data(), z.data()), "the coordinates");
    for (std::size_t i = 0; i < x.size(); ++i) {
      const int g = f->node_map[i];
      if (g < 0 || g >= global_nodes) f->fail("node number " + std::to_string(g + 1) + " beyond the whole mesh's");
      whole.coordinates[3 * static_cast<std::size_t>(g)] = x[i];
      whole.coordinates[3 * static_cast<std::size_t>(g) + 1] = y[i];
      whole.coordinates[3 * static_cast<std::size_t>(g) + 2] = z[i];
      seen[static_cast<std::size_t>(g)] = 1;
    }
  }
  if (std::find(seen.begin(), seen.end(), 0) != seen.end())
    throw BadInput(files[0]->path + ": the rank files do not cover every node of the whole mesh; join the files of one run");
  const RankFile& f0 = *files[0];
  const auto sets = [&](ex_entity_type type) {
    const int count = static_cast<int>(ex_inquire_int(f0.handle(), type == EX_NODE_SET ? EX_INQ_NODE_SETS : EX_INQ_SIDE_SETS));
    const auto names = names_of(f0.handle(), type, count, f0);
    for (int s = 1; s <= count; ++s) {
      std::vector<int> nodes;
      std::vector<mesh::Side> sides;
      for (const auto& f : files) {
        int size = 0, factors = 0;
        f->check(ex_get_set_param(f->handle(), type, s, &size, &factors), "a set");
        if (size == 0) continue;
        std::vector<int> entries(static_cast<std::size_t>(size)), extra(static_cast<std::size_t>(size));
        f->check(ex_get_set(f->handle(), type, s, entries.data(), type == EX_SIDE_SET ? extra.data() : nullptr), "a set");
        for (int i = 0; i < size; ++i) {
          const int local = entries[static_cast<std::size_t>(i)] - 1;
          if (local < 0 || local >= (type == EX_NODE_SET ? f->nodes : f->elements)) f->fail("a set member beyond the file's");
          if (type == EX_NODE_SET)
            nodes.push_back(f->node_map[static_cast<std::size_t>(local)]);
          else
            sides.push_back({f->element_map[static_cast<std::size_t>(local)], extra[static_cast<std::size_t>(i)] - 1});
        }
      }
      // A shared node is in every holder's set: once in the whole mesh's. Both lists sorted, as the mesh keeps them.
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      std::sort(sides.begin(), sides.end());
      if (type == EX_NODE_SET)
        whole.node_sets[names[static_cast<std::size_t>(s - 1)]] = std::move(nodes);
      else
        whole.side_sets[names[static_cast<std::size_t>(s - 1)]] = std::move(sides);
    }
  };
  sets(EX_NODE_SET);
  sets(EX_SIDE_SET);
}

// The joined file's variables: rank 0's names, which every rank's must equal; the times likewise.
struct Variables {
  std::vector<std::string> global, nodal, element;
  std::vector<double> times;
};

// The files of one rank count, open (up to the limit), with their variables and times.
struct RankSet {
  int ranks = 0;
  std::vector<std::unique_ptr<RankFile>> files;
  Variables variables;
};

// One step of the joined file: step `step` (1-based) of `set`'s files.
struct StepSource {
  const RankSet* set = nullptr;
  int step = 0;
};

Variables read_variables(const std::vector<std::unique_ptr<RankFile>>& files) {
  Variables v;
  for (const auto& f : files) {
    Variables mine{variable_names(*f, EX_GLOBAL), variable_names(*f, EX_NODAL), variable_names(*f, EX_ELEM_BLOCK), {}};
    const int steps = static_cast<int>(ex_inquire_int(f->handle(), EX_INQ_TIME));
    mine.times.resize(static_cast<std::size_t>(std::max(steps, 0)));
    if (steps > 0) f->check(ex_get_all_times(f->handle(), mine.times.data()), "the times");
    if (f == files[0]) {
      v = std::move(mine);
      continue;
    }
    if (mine.global != v.global || mine.nodal != v.nodal || mine.element != v.element)
      f->fail("its variables are not rank 0's");
    if (mine.times != v.times)
      f->fail("it holds " + std::to_string(mine.times.size()) + " steps where rank 0's holds " +
              std::to_string(v.times.size()) + " (or other times)");
  }
  return v;
}

void define_variables(int out, const Variables& v, int blocks, const std::string& path) {
  const auto check = [&](int status, const char* what) {
    if (status < 0) throw BadInput(path + ": cannot write " + std::string(what) + "; check the disk space");
  };
  std::size_t longest = 32;
  for (const auto* list : {&v.global, &v.nodal, &v.element})
    for (const auto& n : *list) longest = std::max(longest, n.size());
  check(ex_set_max_name_length(out, static_cast<int>(longest)), "the name length");
  const auto put = [&](ex_entity_type type, const std::vector<std::string>& names) {
    if (names.empty()) return;
    std::vector<char*> p;
    for (const auto& n : names) p.push_back(const_cast<char*>(n.c_str()));  // the API only reads
    check(ex_put_variable_param(out, type, static_cast<int>(names.size())), "the variable names");
    check(ex_put_variable_names(out, type, static_cast<int>(names.size()), p.data()), "the variable names");
  };
  put(EX_GLOBAL, v.global);
  put(EX_NODAL, v.nodal);
  put(EX_ELEM_BLOCK, v.element);
  if (!v.element.empty() && blocks > 0) {
    std::vector<int> table(static_cast<std::size_t>(blocks) * v.element.size(), 1);  // as the writer: all on all
    check(ex_put_truth_table(out, EX_ELEM_BLOCK, blocks, static_cast<int>(v.element.size()), table.data()),
          "the truth table");
  }
}

// Every step of `steps`, in order: one variable of one step in memory at a time (`values`, the whole mesh's rows of it).
void join_steps(const std::vector<StepSource>& steps, const mesh::Mesh& whole, const Variables& v, int out,
                const std::string& path) {
  const auto check = [&](int status, const std::string& what) {
    if (status < 0) throw BadInput(path + ": cannot write " + what + "; check the disk space");
  };
  std::vector<double> values(static_cast<std::size_t>(std::max(whole.node_count(), whole.element_count()))), buffer;
  std::vector<double> globals(v.global.size());
  for (int j = 1; j <= static_cast<int>(steps.size()); ++j) {
    const auto& files = steps[static_cast<std::size_t>(j - 1)].set->files;
    const int k = steps[static_cast<std::size_t>(j - 1)].step;  // in its rank files
    const double time = steps[static_cast<std::size_t>(j - 1)].set->variables.times[static_cast<std::size_t>(k - 1)];
    const std::string step = "step " + std::to_string(k);
    check(ex_put_time(out, j, &time), step + "'s time");
    if (!globals.empty()) {
      files[0]->check(ex_get_glob_vars(files[0]->handle(), k, static_cast<int>(globals.size()), globals.data()), step);
      check(ex_put_glob_vars(out, j, static_cast<int>(globals.size()), globals.data()), step + "'s global variables");
    }
    for (int var = 1; var <= static_cast<int>(v.nodal.size()); ++var) {
      for (const auto& f : files) {
        buffer.resize(static_cast<std::size_t>(f->nodes));
        f->check(ex_get_var(f->handle(), k, EX_NODAL, var, 1, f->nodes, buffer.data()), step + " of '" + v.nodal[var - 1] + "'");
        for (std::size_t i = 0; i < buffer.size(); ++i) values[static_cast<std::size_t>(f->node_map[i])] = buffer[i];
      }
      check(ex_put_var(out, j, EX_NODAL, var, 1, whole.node_count(), values.data()), step + " of '" + v.nodal[var - 1] + "'");
    }
    for (int var = 1; var <= static_cast<int>(v.element.size()); ++var)
      for (std::size_t b = 0; b < whole.blocks.size(); ++b) {
        const auto& blk = whole.blocks[b];
        for (const auto& f : files) {
          const int count = f->block_counts[b];
          if (count == 0) continue;
          buffer.resize(static_cast<std::size_t>(count));
          f->check(ex_get_var(f->handle(), k, EX_ELEM_BLOCK, var, f->block_ids[b], count, buffer.data()),
                   step + " of '" + v.element[var - 1] + "'");
          for (int i = 0; i < count; ++i)
            values[static_cast<std::size_t>(f->element_map[static_cast<std::size_t>(f->block_first[b] + i)])] = buffer[i];
        }
        check(ex_put_var(out, j, EX_ELEM_BLOCK, var, static_cast<int>(b + 1), blk.element_count, values.data() + blk.first_element),
              step + " of '" + v.element[var - 1] + "'");
      }
  }
}

// The info records of rank 0's file: the length unit first (solver/output/README.md "Length unit"), then notes.
mesh::ExodusLengthUnit info_records(const RankFile& f, std::vector<std::string>& notes) {
  const int count = static_cast<int>(ex_inquire_int(f.handle(), EX_INQ_INFO));
  std::vector<std::vector<char>> buffers(static_cast<std::size_t>(std::max(count, 0)), std::vector<char>(MAX_LINE_LENGTH + 1, '\0'));
  std::vector<char*> p;
  for (auto& b : buffers) p.push_back(b.data());
  if (count > 0) f.check(ex_get_info(f.handle(), p.data()), "the info records");
  mesh::ExodusLengthUnit unit;  // per_metre 1: the coordinates are copied as the files hold them
  const std::string prefix = mesh::exodus_length_unit_record;
  for (std::size_t k = 0; k < buffers.size(); ++k) {
    const std::string line = buffers[k].data();
    if (k == 0 && line.rfind(prefix, 0) == 0)
      unit.name = line.substr(prefix.size());
    else
      notes.push_back(line);
  }
  return unit;
}

// A results.exo already there may be replaced only when this folder's manifest lists it as written by
// its run (a one-rank run's, or an earlier join's): a user's file is never touched.
void check_target(const std::string& folder, const fs::path& target) {
  mesh::require_output_target(target.string());
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(target, ec))) return;
  const auto manifest = solver::read_manifest(folder);
  const auto* entry = manifest ? manifest->find("results.exo") : nullptr;
  if (!entry || !solver::written_by_run(folder, *entry, manifest->run_id))
    throw BadInput(target.string() + " exists and is not a file this folder's run wrote (its manifest does not list it "
                                     "as written); move it away, then join again");
  // A one-rank segment of the run (a restart 1 -> M or N -> 1) wrote results.exo itself: its steps are in no
  // rank file, so replacing it would lose them.
  for (const auto& g : manifest->segments)
    if (g.ranks == 1)
      throw BadInput(target.string() + " holds the steps of the run's one-rank segment, which no rank file holds; "
                                       "move it away, then join again");
}

void record_in_manifest(const std::string& folder) {
  auto manifest = solver::read_manifest(folder);
  if (!manifest) return;
  manifest->add("results.exo");
  struct stat st{};
  if (lstat((fs::path(folder) / "results.exo").c_str(), &st) != 0) return;
  for (auto& e : manifest->files)
    if (e.name == "results.exo") {
      e.device = static_cast<unsigned long long>(st.st_dev);
      e.inode = static_cast<unsigned long long>(st.st_ino);
    }
  solver::write_manifest(folder, *manifest);
}

}  // namespace

namespace {

// The files of `ranks` ranks, their headers read (at most the limit open at once).
void open_set(const std::string& folder, RankSet& set, OpenLimit& limit) {
  for (int r = 0; r < set.ranks; ++r) {
    set.files.push_back(std::make_unique<RankFile>());
    set.files.back()->limit = &limit;
    set.files.back()->path = (fs::path(folder) / solver::output::rank_file_name(set.ranks, r)).string();
    open_rank(*set.files.back());
  }
  set.variables = read_variables(set.files);
}

// The joined file's steps: each segment's steps in its time window, in order. The other rank counts' files
// must hold the mesh (global counts, blocks) and the variables of `last`, whose files give the mesh.
std::vector<StepSource> pick_steps(const std::vector<solver::RunSegment>& segments, const std::vector<RankSet>& sets,
                                   const RankSet& last, const std::array<int, 2>& global) {
  for (const auto& set : sets) {
    const RankFile& f = *set.files[0];
    int nodes = 0, elements = 0, blocks = 0, node_sets = 0, side_sets = 0;
    f.check(ex_get_init_global(f.handle(), &nodes, &elements, &blocks, &node_sets, &side_sets), "the Nemesis global counts");
    if (nodes != global[0] || elements != global[1] || f.block_ids != last.files[0]->block_ids)
      f.fail("its mesh is not the one of " + last.files[0]->path + " (another run's files?)");
    const Variables& v = set.variables;
    if (v.global != last.variables.global || v.nodal != last.variables.nodal || v.element != last.variables.element)
      f.fail("its variables are not those of " + last.files[0]->path);
  }
  std::vector<StepSource> steps;
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const RankSet& set = *std::find_if(sets.begin(), sets.end(), [&](const RankSet& s) { return s.ranks == segments[k].ranks; });
    const double to = k + 1 < segments.size() ? segments[k + 1].from_time : std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < set.variables.times.size(); ++i) {
      const double t = set.variables.times[i];
      if (t >= segments[k].from_time && t < to) steps.push_back({&set, static_cast<int>(i) + 1});
    }
  }
  return steps;
}

// Writes the joined file through `partial` (removed on any error).
void write_joined(const mesh::Mesh& whole, const RankSet& last, const std::vector<StepSource>& steps,
                  const fs::path& partial) {
  std::vector<std::string> notes;
  const mesh::ExodusLengthUnit unit = info_records(*last.files[0], notes);
  const Variables& variables = last.variables;
  int out = -1;
  try {
    std::size_t longest = 32;  // as the writer: the file's name length fixed at creation, long enough for every name
    for (const auto* list : {&variables.global, &variables.nodal, &variables.element})
      for (const auto& n : *list) longest = std::max(longest, n.size());
    out = mesh::exodus::create_with_mesh(whole, partial.string(), "tribex results", mesh::ExodusFormat::offset64, unit,
                                         notes, false, longest);
    define_variables(out, variables, static_cast<int>(whole.blocks.size()), partial.string());
    join_steps(steps, whole, variables, out, partial.string());
    const int closed = ex_close(out);
    out = -1;
    if (closed < 0) throw BadInput(partial.string() + ": cannot close the joined file; check the disk space");
  } catch (...) {
    if (out >= 0) ex_close(out);
    std::error_code ec;
    fs::remove(partial, ec);
    throw;
  }
}

}  // namespace

JoinReport join_rank_files(const std::string& folder, int ranks) {
  JoinReport report;
  const std::vector<solver::RunSegment> segments = segments_to_join(folder, ranks);
  const fs::path target = fs::path(folder) / "results.exo", partial = fs::path(folder) / ".results.exo.partial";
  check_target(folder, target);
  mesh::require_output_target(partial.string());
  OpenLimit limit(rank_files_allowed());
  std::vector<RankSet> sets;
  sets.reserve(segments.size());  // StepSource points into it
  for (const auto& g : segments)
    if (std::none_of(sets.begin(), sets.end(), [&](const RankSet& s) { return s.ranks == g.ranks; })) {
      sets.emplace_back();
      sets.back().ranks = g.ranks;
      open_set(folder, sets.back(), limit);
    }
  // The mesh from the last segment's files (every segment's is the same mesh: pick_steps checks).
  const RankSet& last = *std::find_if(sets.begin(), sets.end(), [&](const RankSet& s) { return s.ranks == segments.back().ranks; });
  const auto& files = last.files;
  int global_nodes = 0, global_elements = 0, blocks = 0, node_sets = 0, side_sets = 0;
  files[0]->check(ex_get_init_global(files[0]->handle(), &global_nodes, &global_elements, &blocks, &node_sets, &side_sets),
                  "the Nemesis global counts (not a tribex rank file?)");
  mesh::Mesh whole;
  join_blocks(files, whole);
  join_nodes_and_sets(files, global_nodes, whole);
  if (whole.element_count() != global_elements) files[0]->fail("its global element count is not the files' sum");
  const std::vector<StepSource> steps = pick_steps(segments, sets, last, {global_nodes, global_elements});
  write_joined(whole, last, steps, partial);
  std::error_code ec;
  fs::rename(partial, target, ec);
  if (ec) {
    fs::remove(partial, ec);
    throw BadInput(target.string() + ": cannot rename the joined file into place; check the folder's permissions");
  }
  record_in_manifest(folder);
  report.ranks = last.ranks;
  report.segments = static_cast<int>(segments.size());
  report.steps = static_cast<int>(steps.size());
  report.nodes = whole.node_count();
  report.elements = whole.element_count();
  report.path = target.string();
  return report;
}

}  // namespace tribex::join
