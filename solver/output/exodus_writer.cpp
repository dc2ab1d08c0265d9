// SPDX-License-Identifier: MIT
// results.exo (README.md, "Exodus II output").
#include "solver/output/exodus_writer.hpp"

#include <exodusII.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <filesystem>
#include <stdexcept>

#include "mesh/exodus_io.hpp"
#include "mesh/exodus_prescan.hpp"
#include "mesh/mesh_error.hpp"
#include "solver/errors.hpp"
#include "solver/output/exodus_rank_file.hpp"
#include "solver/output/mesh_outline.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {
namespace {

struct FieldSpec {
  std::string name;
  int components = 0;
  double scale = 1.0;  // file value = value x scale: the length unit's per_metre for a field in "m", else 1
  friend bool operator==(const FieldSpec&, const FieldSpec&) = default;
};

std::vector<char*> c_names(const std::vector<std::string>& names) {
  std::vector<char*> p;
  for (const auto& n : names) p.push_back(const_cast<char*>(n.c_str()));  // the API takes char**; it only reads
  return p;
}

struct ExoBlock {
  int id = 0, first = 0, count = 0;
};

std::vector<std::string> read_variable_names(int exo, ex_entity_type type) {
  int count = 0;
  if (ex_get_variable_param(exo, type, &count) < 0 || count <= 0) return {};
  const int length = std::max<int>(static_cast<int>(ex_inquire_int(exo, EX_INQ_DB_MAX_USED_NAME_LENGTH)), 32);
  std::vector<std::vector<char>> buffers(static_cast<std::size_t>(count), std::vector<char>(length + 1, '\0'));
  std::vector<char*> p;
  for (auto& b : buffers) p.push_back(b.data());
  if (ex_get_variable_names(exo, type, count, p.data()) < 0) return {};
  std::vector<std::string> names;
  for (auto& b : buffers) names.emplace_back(b.data());
  return names;
}

}  // namespace

struct ExodusWriter::Impl {
  std::string directory, path;
  int nodes = 0, elements = 0;
  std::vector<ExoBlock> blocks;  // in element order, Exodus ids 1..B
  std::vector<std::string> global_names;
  mesh::ExodusLengthUnit unit;  // of the coordinates and the length fields (a resumed file: its own)
  int exo = -1;  // rank 0
  int steps = 0;
  double last_time = -INFINITY;
  // The fields of the first step; the file's variables (Exodus names), defined once.
  std::vector<FieldSpec> nodal_fields, element_fields;
  bool fields_fixed = false;
  bool variables_defined = false;
  std::vector<std::string> file_global, file_nodal, file_element;  // as in the file
  long long node_rows = 0, element_rows = 0;  // one file per rank: the owned nodes, the rank's elements
  std::vector<double> component;  // one component of one field, whole mesh (rank 0)
  // One file per rank (the rank-part constructor): the file's mesh and Nemesis counts, and the rows of
  // the nodes owned by lower ranks, fetched for every nodal field of a step.
  bool spread = false;
  const parallel::Domain* domain = nullptr;
  output::MeshOutline outline;
  mesh::Mesh file_mesh;
  output::RankGlobals rank_globals;
  std::unique_ptr<output::SharedNodeRows> shared;
  std::deque<std::vector<double>> spread_rows;  // [nodal field] local rows (a deque: spans into it stay valid)
  std::vector<FieldView> spread_views;
  std::vector<double> spread_globals;

  ~Impl() {
    if (exo >= 0) ex_close(exo);
  }

  void create(const mesh::Mesh& mesh) {
    try {
      // The unit is the first info record (read back by mesh::read_exodus); the notes say what it covers.
      const std::vector<std::string> notes = {
          "coordinates and length fields (unit m: displacement, gap) in " + unit.name,
          "every other field SI; the global variables (history.csv columns) SI"};
      // The history columns' names may be longer than Exodus's default 32 (substrate_axis_top_displacement_x).
      std::size_t longest = 32;
      for (const auto& n : global_names) longest = std::max(longest, n.size());
      exo = mesh::exodus::create_with_mesh(spread ? file_mesh : mesh, path, "tribex results",
                                           mesh::ExodusFormat::offset64, unit, notes, spread, longest);
    } catch (const mesh::MeshError& e) {
      throw SetupError(std::string("cannot create results file: ") + e.what() +
                       "; choose another output directory or fix its permissions");
    }
    if (spread && output::put_rank_maps(exo, file_mesh, *domain, outline, rank_globals) < 0)
      throw SetupError("cannot write the number maps and Nemesis records of '" + path + "'" +
                       (mesh::exodus::last_error().empty() ? "" : " (" + mesh::exodus::last_error() + ")") +
                       "; check the disk space");
  }

  std::vector<std::string> exodus_names(const std::vector<FieldSpec>& fields) const {
    std::vector<std::string> names;
    for (const auto& f : fields)
      for (auto& n : ExodusWriter::component_names(f.name, f.components)) names.push_back(std::move(n));
    return names;
  }

  void check(int status, const std::string& what) const {
    if (status < 0)
      throw OutputError("cannot write " + what + " to '" + path + "'" +
                        (mesh::exodus::last_error().empty() ? "" : " (" + mesh::exodus::last_error() + ")") +
                        "; check the disk space; earlier steps stay readable");
  }

  void define(const std::vector<std::string>& global, const std::vector<std::string>& nodal,
              const std::vector<std::string>& element) {
    std::size_t longest = 32;
    for (const auto* list : {&global, &nodal, &element})
      for (const auto& n : *list) longest = std::max(longest, n.size());
    for (const auto* list : {&global, &nodal, &element})
      for (const auto& n : *list)
        if (n.size() > 255) throw OutputError("'" + n + "' is longer than Exodus II's 255 characters; shorten the set name");
    // Names are stored up to 255 characters; this is the length the API passes (default 32).
    check(ex_set_max_name_length(exo, static_cast<int>(longest)), "the name length");
    const auto put = [&](ex_entity_type type, const std::vector<std::string>& names, const char* what) {
      if (names.empty()) return;
      check(ex_put_variable_param(exo, type, static_cast<int>(names.size())), what);
      auto p = c_names(names);
      check(ex_put_variable_names(exo, type, static_cast<int>(names.size()), p.data()), what);
    };
    put(EX_GLOBAL, global, "the global variable names");
    put(EX_NODAL, nodal, "the nodal variable names");
    put(EX_ELEM_BLOCK, element, "the element variable names");
    if (!element.empty() && !blocks.empty()) {
      std::vector<int> table(blocks.size() * element.size(), 1);  // every variable on every block
      check(ex_put_truth_table(exo, EX_ELEM_BLOCK, static_cast<int>(blocks.size()), static_cast<int>(element.size()),
                               table.data()),
            "the element variable truth table");
    }
    file_global = global;
    file_nodal = nodal;
    file_element = element;
    variables_defined = true;
  }

  bool open_for_resume(const mesh::Mesh& mesh, double resume_time);
  // The folder made if missing, then the file continued (a resumed run whose file has its steps) or created.
  void open(const mesh::Mesh& mesh, std::optional<double> resume_time) {
    std::error_code ec;
    std::filesystem::create_directories(directory, ec);
    if (ec || !std::filesystem::is_directory(directory))
      throw SetupError("cannot create output directory '" + directory + "': " +
                       (ec ? ec.message() : std::string("a file of that name exists")) +
                       "; choose another output directory or fix its permissions");
    if (resume_time && open_for_resume(mesh, *resume_time)) return;
    create(mesh);
  }
  void write(double time, std::span<const FieldView> nodal, std::span<const FieldView> element,
             std::span<const double> globals);
};

// A resumed run rewrites results.exo with the steps before the restart time (netCDF cannot drop
// the later ones in place): a copy through `.results.exo.partial`, renamed over the old file.
// Returns false when there is no file to continue.
bool ExodusWriter::Impl::open_for_resume(const mesh::Mesh& mesh, double resume_time) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec) || fs::file_size(path, ec) == 0) return false;
  const std::string refuse = "cannot continue '" + path + "': ";
  const std::string fix = "; move it away or resume into another output folder (-o)";
  int comp_ws = sizeof(double), io_ws = 0;
  float version = 0;
  try {  // the header walk of read_exodus first: the library trusts the file's sizes (mesh/README.md)
    mesh::prescan_exodus_file(path);
  } catch (const mesh::MeshError& e) {
    throw SetupError(refuse + e.what() + fix);
  }
  ex_opts(EX_DEFAULT);
  struct Closer {
    int id = -1;
    ~Closer() {
      if (id >= 0) ex_close(id);
    }
  } old;
  old.id = ex_open(path.c_str(), EX_READ, &comp_ws, &io_ws, &version);
  if (old.id < 0) throw SetupError(refuse + "it is not a readable Exodus II file" + fix);
  // The API cuts names it reads to 32 characters unless told the file's own limit (history columns are longer).
  ex_set_max_name_length(old.id, static_cast<int>(ex_inquire_int(old.id, EX_INQ_DB_MAX_ALLOWED_NAME_LENGTH)));
  char title[MAX_LINE_LENGTH + 1] = {};
  int dim = 0, n = 0, e = 0, nb = 0, nns = 0, nss = 0;
  if (ex_get_init(old.id, title, &dim, &n, &e, &nb, &nns, &nss) < 0 || n != nodes || e != elements ||
      nb != static_cast<int>(blocks.size()))
    throw SetupError(refuse + "it is not the results file of this mesh (" + std::to_string(nodes) + " nodes, " +
                     std::to_string(elements) + " elements)" + fix);
  std::vector<int> old_block_ids(static_cast<std::size_t>(nb));
  if (nb > 0 && ex_get_ids(old.id, EX_ELEM_BLOCK, old_block_ids.data()) < 0)
    throw SetupError(refuse + "cannot read its block ids" + fix);
  const int stored = static_cast<int>(ex_inquire_int(old.id, EX_INQ_TIME));
  std::vector<double> times(static_cast<std::size_t>(std::max(stored, 0)));
  if (stored > 0 && ex_get_all_times(old.id, times.data()) < 0) throw SetupError(refuse + "cannot read its times" + fix);
  int kept = 0;  // the steps before the restart time (the step at it is written again)
  while (kept < stored && times[kept] < resume_time && (kept == 0 || times[kept] > times[kept - 1])) ++kept;
  unit = mesh::exodus::length_unit_of(old.id, path);  // the file's own: its steps are copied as they are
  const auto global = read_variable_names(old.id, EX_GLOBAL);
  const auto nodal = read_variable_names(old.id, EX_NODAL);
  const auto element = read_variable_names(old.id, EX_ELEM_BLOCK);

  const std::string final_path = path;
  const std::string partial = (fs::path(directory) / ("." + fs::path(path).filename().string() + ".partial")).string();
  path = partial;
  try {
    create(mesh);
    if (kept > 0) define(global, nodal, element);
    std::vector<double> values(static_cast<std::size_t>(std::max({nodes, elements, 1})));
    std::vector<double> g(std::max<std::size_t>(global.size(), 1));
    for (int k = 1; k <= kept; ++k) {
      const auto copy = [&](int status, const char* what) {
        if (status < 0) throw SetupError(refuse + "cannot copy step " + std::to_string(k) + "'s " + what + fix);
      };
      copy(ex_put_time(exo, k, &times[k - 1]), "time");
      if (!global.empty()) {
        copy(ex_get_glob_vars(old.id, k, static_cast<int>(global.size()), g.data()), "global variables");
        copy(ex_put_glob_vars(exo, k, static_cast<int>(global.size()), g.data()), "global variables");
      }
      for (int v = 1; v <= static_cast<int>(nodal.size()); ++v) {
        copy(ex_get_var(old.id, k, EX_NODAL, v, 1, nodes, values.data()), "nodal variables");
        copy(ex_put_var(exo, k, EX_NODAL, v, 1, nodes, values.data()), "nodal variables");
      }
      for (int v = 1; v <= static_cast<int>(element.size()); ++v)
        for (std::size_t b = 0; b < blocks.size(); ++b) {
          if (blocks[b].count == 0) continue;  // a rank file's block this rank has no element of
          copy(ex_get_var(old.id, k, EX_ELEM_BLOCK, v, old_block_ids[b], blocks[b].count, values.data()),
               "element variables");
          copy(ex_put_var(exo, k, EX_ELEM_BLOCK, v, blocks[b].id, blocks[b].count, values.data()), "element variables");
        }
    }
    const int closed = ex_close(exo);
    exo = -1;
    if (closed < 0) throw SetupError(refuse + "cannot close the rewritten copy " + partial + fix);
  } catch (...) {
    if (exo >= 0) ex_close(exo);
    exo = -1;
    fs::remove(partial, ec);
    path = final_path;
    throw;
  }
  path = final_path;
  fs::rename(partial, path, ec);
  if (ec) throw SetupError(refuse + "cannot rename the rewritten copy into place: " + ec.message() + fix);
  exo = ex_open(path.c_str(), EX_WRITE, &comp_ws, &io_ws, &version);
  if (exo < 0) throw SetupError(refuse + "cannot reopen the rewritten file" + fix);
  steps = kept;
  if (kept > 0) last_time = times[kept - 1];
  variables_defined = kept > 0;
  return true;
}

std::vector<std::string> ExodusWriter::component_names(const std::string& name, int components) {
  static const char* vector[] = {"x", "y", "z"};
  static const char* symmetric[] = {"xx", "yy", "zz", "xy", "yz", "zx"};
  static const char* full[] = {"xx", "xy", "xz", "yx", "yy", "yz", "zx", "zy", "zz"};
  std::vector<std::string> out;
  if (components == 1) return {name};
  for (int c = 0; c < components; ++c) {
    const std::string suffix = components == 3 ? vector[c]
                               : components == 6 ? symmetric[c]
                               : components == 9 ? full[c]
                                                 : std::to_string(c + 1);
    out.push_back(name + "_" + suffix);
  }
  return out;
}

ExodusWriter::ExodusWriter(const std::string& directory, const mesh::Mesh& mesh, std::vector<std::string> global_names,
                           std::optional<double> resume_time, const std::string& length_unit)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.directory = directory;
  m.path = (std::filesystem::path(directory) / "results.exo").string();
  const output::MeshOutline outline = output::outline_of(mesh, length_unit, false);
  m.unit = {outline.unit.name, outline.unit.per_metre};
  m.nodes = static_cast<int>(outline.nodes);
  m.elements = static_cast<int>(outline.elements);
  m.global_names = std::move(global_names);
  std::vector<const mesh::Block*> sorted;
  for (const auto& b : outline.blocks)
    if (b.element_count > 0) sorted.push_back(&b);
  std::sort(sorted.begin(), sorted.end(), [](const auto* a, const auto* b) { return a->first_element < b->first_element; });
  for (std::size_t b = 0; b < sorted.size(); ++b)
    m.blocks.push_back({static_cast<int>(b + 1), sorted[b]->first_element, sorted[b]->element_count});


  m.open(mesh, resume_time);
}

ExodusWriter::ExodusWriter(const std::string& directory, const mesh::Mesh& local, const parallel::Domain& domain,
                           const output::MeshOutline& outline, std::vector<std::string> global_names,
                           std::optional<double> resume_time)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.spread = true;
  m.domain = &domain;
  m.outline = outline;
  m.directory = directory;
  m.path = (std::filesystem::path(directory) / output::rank_file_name(domain.ranks, domain.rank)).string();
  m.unit = {outline.unit.name, outline.unit.per_metre};
  m.global_names = std::move(global_names);
  // Collective first (the set names, the global counts, the shared nodes' owners); files after.
  m.file_mesh = output::rank_file_mesh(local, outline);
  m.rank_globals = output::rank_globals(m.file_mesh, domain);
  m.shared = std::make_unique<output::SharedNodeRows>(domain);
  m.nodes = m.file_mesh.node_count();
  m.elements = m.file_mesh.element_count();
  m.node_rows = domain.owned_node_count();
  m.element_rows = m.elements;
  for (std::size_t b = 0; b < m.file_mesh.blocks.size(); ++b)
    m.blocks.push_back({static_cast<int>(b + 1), m.file_mesh.blocks[b].first_element, m.file_mesh.blocks[b].element_count});
  m.open(m.file_mesh, resume_time);
}

ExodusWriter::~ExodusWriter() = default;

void ExodusWriter::Impl::write(double time, std::span<const FieldView> nodal, std::span<const FieldView> element,
                               std::span<const double> globals) {
  if (!variables_defined) {
    define(global_names, exodus_names(nodal_fields), exodus_names(element_fields));
  } else if (file_global != global_names || file_nodal != exodus_names(nodal_fields) ||
             file_element != exodus_names(element_fields)) {
    throw OutputError("'" + path + "' holds other variables than this run writes (a resumed run whose results "
                      "output changed); resume into another output folder (-o)");
  }
  const int k = steps + 1;
  check(ex_put_time(exo, k, &time), "the time");
  if (!global_names.empty())
    check(ex_put_glob_vars(exo, k, static_cast<int>(globals.size()), globals.data()), "the global variables");
  // The views are the file's rows: the whole mesh's (one rank), or a rank file's (write_step fills the nodes it does not own).
  int var = 0;
  for (std::size_t f = 0; f < nodal_fields.size(); ++f) {
    const int c = nodal_fields[f].components;
    const double* v = nodal[f].values.data();
    for (int j = 0; j < c; ++j) {
      const double s = nodal_fields[f].scale;
      for (int i = 0; i < nodes; ++i) component[i] = s == 1.0 ? v[static_cast<std::size_t>(c) * i + j] : v[static_cast<std::size_t>(c) * i + j] * s;
      ++var;
      check(ex_put_var(exo, k, EX_NODAL, var, 1, nodes, component.data()), "nodal variable '" + file_nodal[var - 1] + "'");
    }
  }
  var = 0;
  for (std::size_t f = 0; f < element_fields.size(); ++f) {
    const int c = element_fields[f].components;
    const double* v = element[f].values.data();
    for (int j = 0; j < c; ++j) {
      const double s = element_fields[f].scale;
      for (int i = 0; i < elements; ++i) component[i] = s == 1.0 ? v[static_cast<std::size_t>(c) * i + j] : v[static_cast<std::size_t>(c) * i + j] * s;
      ++var;
      for (const auto& b : blocks)
        if (b.count > 0)
          check(ex_put_var(exo, k, EX_ELEM_BLOCK, var, b.id, b.count, component.data() + b.first),
              "element variable '" + file_element[var - 1] + "'");
    }
  }
  check(ex_update(exo), "the step");  // on disk now: a killed run keeps it
  ++steps;
  last_time = time;
}

void ExodusWriter::write_step(double time, std::span<const FieldView> nodal, std::span<const FieldView> element,
                              std::span<const double> globals) {
  Impl& m = *impl_;
  // Checks first (every rank has the same lists, so every rank throws alike).
  if (!std::isfinite(time)) throw std::invalid_argument("ExodusWriter: time is not finite");
  if (globals.size() != m.global_names.size())
    throw std::invalid_argument("ExodusWriter: " + std::to_string(globals.size()) + " global values for " +
                                std::to_string(m.global_names.size()) + " global variables");
  const long long node_rows = m.spread ? m.node_rows : m.nodes;
  const long long element_rows = m.spread ? m.element_rows : m.elements;
  std::vector<FieldSpec> ns, es;
  for (const auto* list : {&nodal, &element}) {
    const bool is_nodal = list == &nodal;
    for (const auto& f : *list) {
      if (f.name.empty() || f.components < 1 ||
          f.values.size() != static_cast<std::size_t>(f.components) * static_cast<std::size_t>(is_nodal ? node_rows : element_rows))
        throw std::invalid_argument("ExodusWriter: field '" + f.name + "' has " + std::to_string(f.values.size()) +
                                    " values, not components x rows");
      (is_nodal ? ns : es).push_back({f.name, f.components, f.unit == "m" ? m.unit.per_metre : 1.0});
    }
  }
  if (!m.fields_fixed) {
    m.nodal_fields = ns;
    m.element_fields = es;
    m.fields_fixed = true;
    m.component.resize(static_cast<std::size_t>(std::max(m.nodes, m.elements)));
  } else if (ns != m.nodal_fields || es != m.element_fields) {
    throw std::invalid_argument("ExodusWriter: every step must carry the first step's fields");
  }
  if (m.steps > 0 && !(time > m.last_time))
    throw std::invalid_argument("ExodusWriter: time " + std::to_string(time) + " does not follow the last step's");

  if (m.spread) {
    // The owned rows as given, the other nodes' rows from their owners (collective); rank 0's globals.
    m.spread_views.clear();
    m.spread_rows.resize(std::max(m.spread_rows.size(), nodal.size()));
    for (std::size_t f = 0; f < nodal.size(); ++f) {
      m.shared->fill(nodal[f].values.data(), nodal[f].components, m.spread_rows[f]);
      m.spread_views.push_back({nodal[f].name, nodal[f].components, m.spread_rows[f], nodal[f].unit});
    }
    m.spread_globals.assign(globals.begin(), globals.end());
    if (!m.spread_globals.empty())
      MPI_Bcast(m.spread_globals.data(), static_cast<int>(m.spread_globals.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  }
  if (!m.spread) {
    m.write(time, nodal, element, globals);
    return;
  }
  std::string failure;
  try {
    m.write(time, m.spread_views, element, m.spread_globals);
  } catch (const OutputError& e) {
    failure = e.what();
  }
  {
    // Each rank writes its own file: the lowest rank that failed says why, on every rank.
    int first = failure.empty() ? m.domain->ranks : m.domain->rank;
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first < m.domain->ranks) {
      parallel::broadcast(failure, first);
      throw OutputError(failure);
    }
  }
}

void ExodusWriter::flush() {
  if (impl_->exo >= 0 && ex_update(impl_->exo) < 0)
    throw OutputError("cannot flush '" + impl_->path + "'; check the disk space");
}

int ExodusWriter::step_count() const { return impl_->steps; }
const std::string& ExodusWriter::path() const { return impl_->path; }

}  // namespace tribex::solver
