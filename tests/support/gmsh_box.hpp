// SPDX-License-Identifier: MIT
// A box meshed by gmsh's own mesher, for the tests of our gmsh readers (tests/mesh/test_gmsh_io.cpp,
// tests/parallel_unit/mpi/msh_slab_test.cpp): an OCC box 1 x 2 x 0.5 in the current gmsh model (open a
// GmshSession and a GmshScratchModel first), its curves transfinite with `intervals` along x, y and z and its
// surfaces recombined, so that generate(3) gives hexes; and the physical groups both tests write.
#pragma once

#include <gmsh.h>

#include <array>

namespace tribex::test {

inline void add_transfinite_gmsh_box(const std::array<int, 3>& intervals) {
  gmsh::model::occ::addBox(0, 0, 0, 1.0, 2.0, 0.5);
  gmsh::model::occ::synchronize();
  gmsh::vectorpair curves, surfaces;
  gmsh::model::getEntities(curves, 1);
  for (const auto& [dim, tag] : curves) {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
    gmsh::model::mesh::setTransfiniteCurve(tag, (x1 - x0 > 0.1 ? intervals[0] : y1 - y0 > 0.1 ? intervals[1] : intervals[2]) + 1);
  }
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [dim, tag] : surfaces) {
    gmsh::model::mesh::setTransfiniteSurface(tag);
    gmsh::model::mesh::setRecombine(dim, tag);
  }
  gmsh::model::mesh::setTransfiniteVolume(1);
}

// The box's physical groups: the volume "solid", the top face "top" and the corner at the origin as an
// unnamed point group 7 (read as node set "nodes_7").
inline void add_gmsh_box_groups() {
  gmsh::vectorpair top, corner;
  gmsh::model::setPhysicalName(3, gmsh::model::addPhysicalGroup(3, {1}), "solid");
  gmsh::model::getEntitiesInBoundingBox(-0.1, -0.1, 0.4, 1.1, 2.1, 0.6, top, 2);
  gmsh::model::getEntitiesInBoundingBox(-0.1, -0.1, -0.1, 0.1, 0.1, 0.1, corner, 0);
  gmsh::model::setPhysicalName(2, gmsh::model::addPhysicalGroup(2, {top.at(0).second}), "top");
  gmsh::model::addPhysicalGroup(0, {corner.at(0).second}, 7);
}

}  // namespace tribex::test
