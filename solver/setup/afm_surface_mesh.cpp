// SPDX-License-Identifier: MIT
#include "solver/setup/afm_surface_mesh.hpp"

#include "mesh/afm/afm_mesh.hpp"
#include "mesh/mesh_error.hpp"
#include "solver/errors.hpp"

namespace tribex::solver {

mesh::Mesh build_afm_surface_mesh(const inputs::AfmSurfaceSpec& spec) {
  mesh::afm::AfmMeshSpec m;
  m.window = spec.window;
  m.track = spec.track;
  m.element_size = spec.element_size;
  m.depth = spec.depth;
  m.coating_thickness = spec.coating_thickness;
  m.coating_layers = spec.coating_layers;
  m.grading_ratio = spec.grading_ratio;
  m.interpolate_small_window = spec.interpolate_small_window;
  try {
    return mesh::afm::mesh_afm_file(spec.file, spec.channel, m);
  } catch (const mesh::MeshError& e) {
    throw SetupError(spec.where.str() + ": error: 'begin afm surface': " + e.what());
  }
}

}  // namespace tribex::solver
