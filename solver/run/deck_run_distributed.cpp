// SPDX-License-Identifier: MIT
// run_deck, stage 1 with `begin decomposition` / `set-up = distributed` (issue 57 scope 2; solver/README.md
// "Parallel runs"): every rank makes its own part of a generated mesh, no rank holds the whole mesh.
// What the serial set-up (deck_run_setup.cpp, DeckRun::build_parts) does on rank 0's whole mesh is done
// here from the plan (mesh/generated_plan.hpp) or from the parts:
//   - the partition: PT-Scotch on the slabs' dual graph, elements exchanged (parallel/generated_parts.hpp);
//   - "every node in an element": true of a generated mesh by construction (node_holders' check);
//   - the element check (mesh::validate): each rank on its part, agreed on;
//   - the contact faces, the contact's travel (the scale of the patches' cuts) and the contact patches:
//     each rank from the plan's side sets (the surfaces' elements alone; parallel/generated_parts.hpp);
//   - the mesh's SHA-256 (restart files): rank 0 streams the mesh through the hash in chunks;
//   - results.h5's outline: counts and blocks from the plan, the length unit from the extent reduced
//     over the parts.
// Left: results.exo (written by rank 0 from the whole mesh: such a run is set up serially, and the log
// says why), and the meshes generated_plan cannot describe (solver/model.hpp).
#include <malloc.h>

#include <chrono>
#include <cmath>

#include "mesh/mesh_error.hpp"
#include "solver/parallel/contact_travel.hpp"
#include "solver/parallel/generated_parts.hpp"
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

}  // namespace

bool DeckRun::build_parts_distributed() {
  std::string why;
  std::optional<mesh::GeneratedPlan> plan;
  std::exception_ptr error;
  try {
    plan = generated_plan(deck_, why);  // every rank alike: the same deck, the same plan or error
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_errors(error);
  if (plan && region_.results && region_.results->exodus) {
    plan.reset();
    why = "results.exo is written by rank 0 from the whole mesh";
  }
  if (!plan) {
    log_.say("set-up = distributed: the mesh is made on rank 0 instead (" + why + ")");
    return false;
  }
  // As on rank 0 in the serial set-up: each large temporary freed goes back to the system at once.
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
  const auto start = std::chrono::steady_clock::now();
  parallel::GeneratedPart g;
  ContactFaces contact;
  std::optional<ContactTravel> travel;
  parallel::AxisScale scale = parallel::kUnitScale;
  // Each stage on every rank alike (the same plan, the same deck), each agreed on before the next collective.
  const auto partition_error = [&](const std::runtime_error& e) {  // rank 0 says it, once
    error = std::make_exception_ptr(SetupError(std::string("cannot partition the mesh for ") + std::to_string(ranks_) +
                                               " ranks: " + e.what() + "; run with fewer ranks (mpirun -np N)"));
  };
  std::vector<int> slab_part;
  try {
    slab_part = parallel::generated_slab_parts(*plan);
  } catch (const std::runtime_error& e) {
    partition_error(e);
  }
  agree_on_errors(error);
  std::optional<inputs::ContactSpec> enforced;
  try {
    if (region_.contact) {
      // As the serial set-up on rank 0's whole mesh, from the plan.
      contact = contact_faces(*plan, *region_.contact);
      travel = contact_travel(deck_, *plan);
      scale = decomposition_scale(region_.decomposition, travel, ranks_);
      mesh::Mesh blocks;  // block_wave_moduli reads the blocks alone
      blocks.blocks = plan->blocks;
      enforced = as_enforced(*region_.contact, contact, block_wave_moduli(deck_, blocks));
    }
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_errors(error);
  try {
    parallel::place_generated_patches(*plan, enforced ? &*enforced : nullptr, slab_part, scale);
    g = parallel::generated_part(*plan, std::move(slab_part));
  } catch (const std::runtime_error& e) {
    partition_error(e);
  }
  agree_on_errors(error);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    validate_part(g.part, "generated mesh of finite element model '" + deck_.procedure.region.finite_element_model + "'");
  } catch (...) {
    error = std::current_exception();
  }
  agree_on_errors(error);
  if (root_) mesh_hash_ = mesh_sha256(*plan);
  parallel::broadcast(mesh_hash_, 0);
  report_distributed_partition(g.part, g.shared_nodes, scale, travel, seconds);
  if (region_.results && region_.results->xdmf) {
    output::MeshOutline o;
    o.nodes = plan->node_count;
    o.elements = plan->element_count;
    o.blocks = plan->blocks;
    o.unit = distributed_length_unit(region_.results->length_unit, g.part.mesh);
    results_outline_ = std::move(o);
  }
  plan.reset();
  for (const auto& [name, size] : g.part.node_set_size) set_size_[name] = double(size);
  model_.emplace(build_model(deck_, std::move(g.part), contact));
  return true;
}

void DeckRun::report_distributed_partition(const parallel::MeshPart& mine, long long shared,
                                          const parallel::AxisScale& scale, const std::optional<ContactTravel>& travel,
                                          double seconds) {
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
                  "distributed: each rank generated a slab of the elements, none the whole mesh)%s; %d-%d elements per "
                  "rank; %lld nodes on partition boundaries; partitioned in %.3g s; every rank builds only its part",
                  ranks_, patches.c_str(), fewest, most, shared, seconds));
}

}  // namespace tribex::solver
