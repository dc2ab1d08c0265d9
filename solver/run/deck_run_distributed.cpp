// SPDX-License-Identifier: MIT
// run_deck, stage 1 with `begin decomposition` / `set-up = distributed` (issue 57 scope 2; solver/README.md
// "Parallel runs"): every rank makes its own part of the mesh, no rank holds the whole mesh. The mesh comes
// from an element source (parallel/element_source.hpp): a generated mesh's plan (mesh/generated_plan.hpp)
// or an Exodus II or MSH 4.1 file read in slices (parallel/file_slice_source.hpp, mesh/mesh_slices.hpp). What the serial set-up
// (deck_run_setup.cpp, DeckRun::build_parts) does on rank 0's whole mesh is done here from the source or
// from the parts:
//   - the partition: PT-Scotch on the slabs' dual graph, elements exchanged (parallel/source_parts.hpp);
//   - "every node in an element": true of a generated mesh by construction; an Exodus source drops the
//     nodes no element uses and renumbers the others, as read_exodus does;
//   - the element check (mesh::validate): each rank on its part, agreed on;
//   - the contact faces, the contact's travel (the scale of the patches' cuts) and the contact patches:
//     each rank from the surfaces' elements alone (parallel/source_parts.hpp);
//   - the mesh's SHA-256 (restart files): rank 0 streams the mesh through the hash in chunks;
//   - results.h5's outline: counts and blocks from the source, the length unit from the extent reduced
//     over the parts.
// Left: results.exo (written by rank 0 from the whole mesh: such a run is set up serially, and the log
// says why), the meshes neither source can describe (solver/model.hpp), and an Exodus deck whose contact
// travels along a tangential prescribed motion without `coordinate scale` (the travel needs the mesh's
// connected pieces).
#include <malloc.h>

#include <chrono>
#include <cmath>
#include <memory>

#include "mesh/mesh_error.hpp"
#include "mesh/msh_slices.hpp"
#include "solver/parallel/contact_travel.hpp"
#include "solver/parallel/file_slice_source.hpp"
#include "solver/parallel/source_parts.hpp"
#include "solver/restart/run_fingerprint.hpp"
#include "solver/run/deck_run.hpp"

namespace tribex::solver {
namespace {

// mesh::validate on a part, the element named by its global number (the serial message's numbering).
void validate_part(const parallel::MeshPart& p, const std::string& source) {
  try {
    mesh::validate(p.mesh, source);
  } catch (const mesh::MeshError&) {
    for (int e = 0; e < p.mesh.element_count(); ++e) {
      mesh::Mesh one;  // the element alone, so that the message names it as element 1
      for (int a = 0; a < 8; ++a) {
        const int n = p.mesh.connectivity[8 * static_cast<std::size_t>(e) + a];
        one.connectivity.push_back(a);
        for (int i = 0; i < 3; ++i) one.coordinates.push_back(p.mesh.coordinates[3 * static_cast<std::size_t>(n) + i]);
      }
      one.blocks.push_back({"block", 0, 1});
      try {
        mesh::validate(one, source);
      } catch (const mesh::MeshError& e1) {
        throw mesh::MeshError(source + ": element " + std::to_string(p.global_element[e] + 1) +
                              " is inverted or degenerate (" + e1.what() + ")");
      }
    }
    throw;
  }
}

// The whole mesh's length unit from the parts' boxes reduced over the ranks (output::resolve_length_unit).
output::LengthUnit distributed_length_unit(const std::string& choice, const mesh::Mesh& part) {
  mesh::BoundingBox box = mesh::bounding_box(part);
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = parallel::min(box.lo[i]);
    box.hi[i] = parallel::max(box.hi[i]);
  }
  return output::resolve_length_unit(choice, box);
}

// An Exodus file's source. Rank 0 opens the file first and walks its netCDF header (read_exodus's checks,
// the file's first 16 MiB); the other ranks, once it has, open it with the header's remaining checks only
// (not P reads of 16 MiB).
std::unique_ptr<parallel::FileSliceSource> file_slice_source(const std::string& path) {
  std::unique_ptr<parallel::FileSliceSource> exodus;
  std::exception_ptr error;
  for (const bool first : {true, false}) {
    try {
      if (first == parallel::is_root()) exodus = std::make_unique<parallel::FileSliceSource>(path, first);
    } catch (const mesh::MeshError& e) {
      error = std::make_exception_ptr(SetupError(e.what()));
    } catch (...) {
      error = std::current_exception();
    }
    agree_on_errors(error);
  }
  return exodus;
}

// An MSH 4.1 file's source: rank 0 walks the file for its index (mesh/msh_slices.hpp: a stream through a
// 1 MiB buffer, msh_prescan's checks) and broadcasts it (a few kB: one walk, not P); then every rank reads its
// slices. None, with the reason in `why` (every rank alike: it is in the index), for a file that is not sliced
// (MSH 2.2, ...): the serial reader reads it.
std::unique_ptr<parallel::FileSliceSource> msh_source(const std::string& path, std::string& why) {
  std::unique_ptr<mesh::MshSlices> file;
  std::string index;
  std::exception_ptr error;
  const auto agree = [&](auto&& step) {
    try {
      step();
    } catch (const mesh::MeshError& e) {
      error = std::make_exception_ptr(SetupError(e.what()));
    } catch (...) {
      error = std::current_exception();
    }
    agree_on_errors(error);
  };
  agree([&] {
    if (!parallel::is_root()) return;
    file = std::make_unique<mesh::MshSlices>(path);
    index = file->index();
  });
  parallel::broadcast(index, 0);
  if (!parallel::is_root()) file = std::make_unique<mesh::MshSlices>(path, index);
  if (!file->unsupported().empty()) {
    why = "the gmsh file is not read in slices: it holds " + file->unsupported();
    return nullptr;
  }
  std::unique_ptr<parallel::FileSliceSource> source;
  agree([&] { source = std::make_unique<parallel::FileSliceSource>(std::move(file)); });
  return source;
}

// The deck's mesh as an element source, or none with the reason in `why` (every rank alike). Collective:
// an Exodus or MSH 4.1 file is opened and read in slices on every rank, its errors agreed on (a bad file:
// exit 2, the lowest failing rank's one line, nothing written).
std::unique_ptr<parallel::ElementSource> element_source(const inputs::Deck& deck, std::string& why) {
  std::unique_ptr<parallel::ElementSource> source;
  std::optional<std::string> path;
  bool gmsh = false;
  std::exception_ptr error;
  try {
    std::string not_file;
    if (auto plan = generated_plan(deck, why)) source = std::make_unique<parallel::PlanSource>(std::move(*plan));
    else if (!(path = mesh_slices_path(deck, not_file, gmsh)) && !not_file.empty()) why = not_file;  // a file's reason
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_errors(error);
  if (!path) return source;
  std::unique_ptr<parallel::FileSliceSource> file = gmsh ? msh_source(*path, why) : file_slice_source(*path);
  if (!file) return nullptr;
  try {
    file->route();  // the nodes no element uses dropped as the serial readers drop them; gmsh's quads matched
  } catch (const mesh::MeshError& e) {
    error = std::make_exception_ptr(SetupError(e.what()));
  }
  agree_on_errors(error);
  why.clear();
  return file;
}

// The contact faces, as contact_faces(whole mesh) makes them, from the surfaces' elements alone.
// `surfaces`: the surfaces' elements (their side sets whole), `global_node` its nodes' global numbers.
ContactFaces source_contact_faces(const inputs::ContactSpec& contact, const mesh::Mesh& surfaces,
                                  const std::vector<int>& global_node) {
  ContactFaces faces = contact_faces(surfaces, contact);
  for (int& n : faces.global_node) n = global_node[static_cast<std::size_t>(n)];
  return faces;
}

}  // namespace

bool DeckRun::build_parts_distributed(int at_least) {
  // As on rank 0 in the serial set-up: each large temporary freed goes back to the system at once.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  std::string why;
  std::unique_ptr<parallel::ElementSource> source = element_source(deck_, why);
  const char* asked = at_least > 0 ? "method = auto" : "set-up = distributed";
  if (source && source->element_count() < at_least) {  // counted from the plan or the file's index, nothing made
    log_.say(format("method = auto: %d elements, fewer than 'distributed above' (%d): the mesh is made on rank 0 and "
                    "METIS partitions it",
                    source->element_count(), at_least));
    return false;
  }
  ContactFaces contact;
  std::optional<ContactTravel> travel;
  parallel::AxisScale scale = parallel::kUnitScale;
  std::optional<inputs::ContactSpec> enforced;
  if (source && region_.contact && !distributed_contact(*source, contact, travel, scale, enforced, why)) source.reset();
  if (!source) {
    log_.say(std::string(asked) + ": the mesh is made on rank 0 instead (" + why + ")");
    return false;
  }
  const auto start = std::chrono::steady_clock::now();
  std::exception_ptr error;
  // Each stage on every rank alike (the same source, the same deck), each agreed on before the next collective.
  const auto partition_error = [&](const std::runtime_error& e) {  // rank 0 says it, once
    error = std::make_exception_ptr(SetupError(std::string("cannot partition the mesh for ") + std::to_string(ranks_) +
                                               " ranks: " + e.what() + "; run with fewer ranks (mpirun -np N)"));
  };
  std::vector<int> slab_part;
  parallel::SourcePart g;
  try {
    slab_part = parallel::slab_parts(*source);
  } catch (const std::runtime_error& e) {
    partition_error(e);
  }
  agree_on_errors(error);
  try {
    parallel::place_source_patches(*source, enforced ? &*enforced : nullptr, slab_part, scale);
    g = parallel::source_part(*source, std::move(slab_part));
  } catch (const std::runtime_error& e) {
    partition_error(e);
  }
  agree_on_errors(error);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  finish_distributed_parts(*source, g, scale, travel, seconds);
  source.reset();  // the plan, or the file's slices and routed sets (and the open file): not held while the model is built
  model_.emplace(build_model(deck_, std::move(g.part), contact));
  return true;
}

bool DeckRun::distributed_contact(const parallel::ElementSource& source, ContactFaces& contact,
                                  std::optional<ContactTravel>& travel, parallel::AxisScale& scale,
                                  std::optional<inputs::ContactSpec>& enforced, std::string& why) {
  // As the serial set-up on rank 0's whole mesh, from the surfaces' elements alone (collective).
  std::vector<int> global_node;
  const mesh::Mesh surfaces = source.elements_mesh(parallel::contact_elements(source, *region_.contact), global_node);
  std::exception_ptr error;
  const auto* plan = dynamic_cast<const parallel::PlanSource*>(&source);
  try {
    contact = source_contact_faces(*region_.contact, surfaces, global_node);
    if (plan) {
      travel = contact_travel(deck_, plan->plan());
    } else {
      // No connected pieces without the whole mesh: a travel that may exist needs the serial set-up unless
      // the deck's `coordinate scale` decides the cuts itself.
      std::vector<std::string> sets;
      for (const auto& [name, size] : source.node_set_sizes()) sets.push_back(name);
      if (!region_.decomposition.coordinate_scale && contact_travel_one_piece(deck_, surfaces, sets))
        why = "the contact's travel along a prescribed motion needs the mesh's connected pieces; give "
              "`coordinate scale` in `begin decomposition` to set it up distributed";
    }
    scale = decomposition_scale(region_.decomposition, travel, ranks_);
    mesh::Mesh blocks;  // block_wave_moduli reads the blocks alone
    blocks.blocks = source.blocks();
    enforced = as_enforced(*region_.contact, contact, block_wave_moduli(deck_, blocks));
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_errors(error);
  return why.empty();
}

void DeckRun::finish_distributed_parts(const parallel::ElementSource& source, parallel::SourcePart& g,
                                       const parallel::AxisScale& scale, const std::optional<ContactTravel>& travel,
                                       double seconds) {
  const auto* plan = dynamic_cast<const parallel::PlanSource*>(&source);
  const auto* exodus = dynamic_cast<const parallel::FileSliceSource*>(&source);
  std::exception_ptr error;
  try {
    validate_part(g.part, plan ? "generated mesh of finite element model '" + deck_.procedure.region.finite_element_model + "'"
                               : exodus->file().path());
    // Rank 0 streams the mesh through the hash (a file opened again: a read error is agreed on, not a hang).
    if (root_) mesh_hash_ = plan ? mesh_sha256(plan->plan()) : mesh_sha256(*exodus->file().reopen(false));
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_errors(error);
  parallel::broadcast(mesh_hash_, 0);
  report_distributed_partition(g.part, g.shared_nodes, scale, travel, seconds,
                               plan ? "generated a slab of the elements" : "read a slab of the elements from the file");
  if (region_.results) {
    output::MeshOutline o;
    o.nodes = source.node_count();
    o.elements = source.element_count();
    o.blocks = source.blocks();
    o.unit = distributed_length_unit(region_.results->length_unit, g.part.mesh);
    results_outline_ = std::move(o);
  }
  for (const auto& [name, size] : g.part.node_set_size) set_size_[name] = double(size);
}

void DeckRun::report_distributed_partition(const parallel::MeshPart& mine, long long shared,
                                          const parallel::AxisScale& scale, const std::optional<ContactTravel>& travel,
                                          double seconds, const char* each_rank) {
  const int elements = static_cast<int>(mine.global_element.size());
  const int fewest = -static_cast<int>(parallel::max(static_cast<long long>(-elements)));
  const int most = static_cast<int>(parallel::max(static_cast<long long>(elements)));
  // The scale as the serial line gives it (report_partition), with the travel that chose it.
  const bool scaled = scale[0] != 1.0 || scale[1] != 1.0 || scale[2] != 1.0;
  const bool chosen = !region_.decomposition.coordinate_scale && travel && crosses_patches(*travel, ranks_);
  const std::string why = chosen ? format(": contact travels %.3g m along %c, node set %s", travel->distance,
                                          "xyz"[travel->axis], travel->node_set.c_str())
                                 : std::string();
  const std::string sides = scaled ? format(" (sides scaled %g %g %g%s)", scale[0], scale[1], scale[2], why.c_str())
                                   : std::string();
  const std::string patches =
      region_.contact ? ", contact surfaces in one compact patch per rank" + sides : std::string();
  log_.say(format("parallel: %d ranks, PT-Scotch k-way partition of the element graph by all the ranks (set-up = "
                  "distributed: each rank %s, none the whole mesh)%s; %d-%d elements per "
                  "rank; %lld nodes on partition boundaries; partitioned in %.3g s; every rank builds only its part",
                  ranks_, each_rank, patches.c_str(), fewest, most, shared, seconds));
}

}  // namespace tribex::solver
