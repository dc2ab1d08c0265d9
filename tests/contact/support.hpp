// SPDX-License-Identifier: MIT
// Small contact problems built in code for the contact unit tests (no deck, no solver): two flat
// slabs, one interaction between two side sets, and force sums over node sets.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/contact_manager.hpp"
#include "mesh/box.hpp"

namespace tribex::contact::test {

constexpr double nm = 1e-9;

// Two slabs for flat-on-flat contact: the master (block "lower") 12 x 12 x 2 nm centred on the
// z axis with its top face (side set lower_zmax) at z = 0, and the slave (block "upper") 2 nm
// thick with its bottom face (upper_zmin) at z = gap. The default grids differ (7 x 7 master
// faces, 20 x 20 slave faces), so that slave nodes project inside master faces.
struct TwoFlats {
  double gap = 0.0;                                        // m
  std::array<int, 2> master_intervals = {7, 7};            // x, y
  std::array<int, 2> slave_intervals = {20, 20};           // x, y
  std::array<double, 2> slave_origin = {-5 * nm, -5 * nm};  // x, y of the slave's lowest corner, m
  std::array<double, 2> slave_size = {10 * nm, 10 * nm};    // x, y, m
};

inline mesh::Mesh two_flats(const TwoFlats& spec) {
  mesh::BoxSpec lower;
  lower.name = "lower";
  lower.origin = {-6 * nm, -6 * nm, -2 * nm};
  lower.size = {12 * nm, 12 * nm, 2 * nm};
  lower.intervals = {spec.master_intervals[0], spec.master_intervals[1], 1};
  mesh::BoxSpec upper;
  upper.name = "upper";
  upper.origin = {spec.slave_origin[0], spec.slave_origin[1], spec.gap};
  upper.size = {spec.slave_size[0], spec.slave_size[1], 2 * nm};
  upper.intervals = {spec.slave_intervals[0], spec.slave_intervals[1], 1};
  mesh::Mesh m = mesh::generate_box(lower);
  mesh::append(m, mesh::generate_box(upper));
  return m;
}

// Adhesion (docs/theory.md 6.2) with `law`: a node counts as in contact within 0.05 z0 of the master,
// and the search reaches twice the cut-off gap.
inline InteractionSettings adhesion_settings(const AdhesionLaw& law, Enforcement enforcement = Enforcement::node_to_face) {
  InteractionSettings s;
  s.law = Adhesion{law, 0.05 * law.z0};
  s.search_margin = 2 * law.cutoff;
  s.enforcement = enforcement;
  return s;
}

// Junction (docs/theory.md 7) with the adhesion `law` and the shear `junction` (its gap tolerance
// also the adhesion's contact rule), search as for adhesion_settings.
inline InteractionSettings junction_settings(const AdhesionLaw& law, const JunctionLaw& junction) {
  InteractionSettings s = adhesion_settings(law);
  s.law = Junction{Adhesion{law, junction.gap_tolerance}, junction};
  return s;
}

// The manager of one interaction `s`: side set `slave_set` of m is surface 0 (the slave),
// `master_set` surface 1 (the master); `mass` [node] the lumped masses, `dt_ref` the step the
// penalty stiffness is scaled with.
inline ContactManager one_interaction(const mesh::Mesh& m, const std::string& slave_set, const std::string& master_set,
                                      InteractionSettings s, const std::vector<double>& mass, double dt_ref = 1e-15) {
  std::vector<ContactSurface> surfaces = {make_surface(m, "slave", {slave_set}), make_surface(m, "master", {master_set})};
  s.slave = 0;
  s.master = 1;
  return ContactManager(std::move(surfaces), {s}, mass, dt_ref, m.node_count());
}

// Component `i` (0 x, 1 y, 2 z) of `force` [node][3] summed over `nodes`, N.
inline double force_sum(const std::vector<double>& force, const std::vector<int>& nodes, int i) {
  double f = 0.0;
  for (int n : nodes) f += force[3 * n + i];
  return f;
}

}  // namespace tribex::contact::test
