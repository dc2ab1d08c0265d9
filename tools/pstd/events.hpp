// SPDX-License-Identifier: MIT
// Detection of pre-sliding tangential deflection (PSTD) events in a PSTD-model run.
//
// In the model the counterface either sticks (R <= C: the normal force is reduced at a fixed position),
// slides (R > C: it advances at constant normal force) or, in between, creeps: it advances a little, sticks,
// is relieved a little, advances again. Creep is the quasi-static advance under decreasing normal force that
// the report calls PSTD (its Figs. 2.21, 2.25, 2.26: position grows while the normal force decreases).
//
// Rule (a = mean contact half-width, taken locally because it varies by orders of magnitude as the normal
// force is reduced along a run):
//   1. mark every position where the counterface had to be lifted (StepRecord::lifted);
//   2. join a marked position to the previous one when they are at most max(dx, gap_factor * a) apart, a at the
//      previous one: between them the counterface advanced without sliding further than a contact radius;
//   3. a joined group of at least 2 lifts is a PSTD event when its extent (last - first marked position) is at
//      least length_factor * a, a averaged over the group: an advance much larger than a contact radius.
#pragma once

#include <cstddef>
#include <vector>

#include "tools/pstd/stepping.hpp"

namespace tribex::pstd {

struct DetectionRule {
  double length_factor = 10.0;  // event extent >= length_factor * a (a: mean half-width over the event)
  double gap_factor = 1.0;      // marked positions at most gap_factor * a apart belong together
};

struct PstdEvent {
  std::size_t first = 0, last = 0;  // indices into Run::steps
  double start = 0.0, end = 0.0;    // positions, m
  double force_start = 0.0, force_end = 0.0;  // departure normal force, N
  double area_start = 0.0, area_end = 0.0;    // m^2
  int contacts_min = 0, contacts_max = 0;
  std::size_t lifts = 0;
  double half_width = 0.0;  // mean contact half-width over the event, m
};

/// Mean contact half-width over the positions [first, last] in contact, m (0 if none in contact).
double mean_half_width(const Run& run, std::size_t first, std::size_t last);
/// Same over the whole run.
double reference_half_width(const Run& run);

std::vector<PstdEvent> detect_pstd(const Run& run, const DetectionRule& rule);

}  // namespace tribex::pstd
