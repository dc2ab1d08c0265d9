// SPDX-License-Identifier: MIT
// Node positions along one axis of the AFM block: uniform elements of at most h inside the track,
// growing geometrically (neighbour ratio <= r) away from it; and layer thicknesses with depth.
#pragma once

#include <vector>

namespace tribex::mesh::afm {

/// Sizes of the elements filling a length L next to an element of size h, ordered away from it:
/// h q, h q^2, ..., h q^n with the fewest n such that q <= r sums to L (q found by bisection,
/// q >= 1). Where even q = 1 would overshoot, ceil(L/h) equal elements of size <= h instead.
/// L <= 0 gives none.
std::vector<double> graded_sizes(double length, double h, double ratio);

/// n+1 increasing node coordinates from lo to hi: uniform elements of size <= h on the track
/// [track_lo, track_hi] (clipped to [lo, hi]), graded_sizes on both sides. A margin thinner than
/// h/4 is absorbed into the track rather than left as a sliver. The ends are set exactly.
std::vector<double> graded_axis(double lo, double hi, double track_lo, double track_hi, double h, double ratio);

}  // namespace tribex::mesh::afm
