// SPDX-License-Identifier: MIT
// The geometry and contact state of the 2-D PSTD model (seed report, Section 2.1.9): a rigid counterface made
// of linked segments over a periodic substrate line, all sampled on one grid (1 nm in the report).
//
// Gap: at travel s (samples) the height difference d_i = z_sub[(start + s + i) mod N] - z_cf[i] is positive
// where the surfaces would overlap if the counterface sat at height H = 0; at height H the local interference
// is d_i - H. Asperities are the summits of d: samples that are the maximum of d over +-m samples (m = the
// curvature span, one source spacing; windows are cut at segment ends). Each summit above H is one Hertzian
// contact (Greenwood-Williamson style, independent asperities) with
//   interference  delta = d_summit - H,
//   curvature     1/R' = -(d[c+m] - 2 d[c] + d[c-m]) / (m dx)^2  (c = summit, moved inward at segment ends),
// which is the sum of both surfaces' curvatures because d = z_sub - z_cf. With this definition the total force
// and area are continuous, monotone functions of H, so the press-in and lift-off root solves are well posed.
#pragma once

#include <cstddef>
#include <vector>

#include "tools/pstd/contact_laws.hpp"

namespace tribex::pstd {

struct Mechanics {
  ContactLaw law = ContactLaw::line_2d;
  double modulus = 0.0;         // E', Pa (effective, see effective_modulus)
  double depth = 1e-6;          // out-of-plane length of the 2-D model, m (forces and areas are per depth * ...)
  double shear_strength = 0.0;  // tau*, Pa; shear capacity F = tau* A (report eq. 2.7)
};

/// One counterface line scan: heights after it was brought into point contact with the substrate at travel 0.
struct Segment {
  std::vector<double> z;  // m
  std::size_t start = 0;  // substrate sample under z[0] at travel 0
  int copy = 0;           // which copy of the counterface (apparent-area study)
};

struct Model {
  double dx = 1e-9;               // grid spacing of every line, m
  std::vector<double> substrate;  // periodic, m
  std::vector<Segment> segments;
  int curvature_span = 1;         // m, samples
  Mechanics mechanics;
  double radius_cap = 1e-5;       // flat summits (1/R' <= 1/radius_cap) are given R' = radius_cap, m
};

/// Bring `segment` into point contact with the substrate at `start`: shift it so that max_i d_i = 0.
Segment place_in_point_contact(const std::vector<double>& substrate, std::vector<double> counterface_z,
                               std::size_t start, int copy);

struct Summit {
  double d = 0.0;       // gap-function value at the summit, m
  double radius = 0.0;  // effective radius R', m
  std::size_t segment = 0;
  std::size_t index = 0;
};

/// Totals at one (travel, H). Forces in N, areas in m^2 (2-D: depth * sum 2a; 3-D: sum pi a^2).
struct ContactState {
  double force = 0.0;
  double area = 0.0;
  double force_rate = 0.0;  // -dF/dH >= 0, N/m
  double area_rate = 0.0;   // -dA/dH >= 0, m
  int contacts = 0;
  double mean_half_width = 0.0;  // m
  double max_interference = 0.0; // m
  int clamped = 0;               // 2-D contacts beyond the law's range (delta >= 4R'e^-2)
};

/// The gap function at one travel and its summits; reused from step to step to avoid reallocations.
class Gap {
 public:
  explicit Gap(const Model& model) : model_(model) {}
  void set_travel(std::size_t travel);
  double highest() const { return highest_; }
  /// Collect the summits with d > threshold (sorted highest first); later evaluations use only these.
  void collect(double threshold);
  double collected_threshold() const { return threshold_; }
  ContactState evaluate(double height) const;
  const std::vector<Summit>& summits() const { return summits_; }

 private:
  const Model& model_;
  std::vector<double> d_;
  std::vector<std::size_t> offsets_;  // segment k occupies d_[offsets_[k], offsets_[k+1])
  std::vector<Summit> summits_;
  double highest_ = 0.0;
  double threshold_ = 0.0;
};

/// Height H at which the summed contact force equals `force` (> 0): the report's press-in in 0.01 nm steps,
/// done as a safeguarded Newton root solve to a relative force error of 1e-13.
double height_for_force(Gap& gap, double force, double interference_guess);

/// The lowest height >= `height` at which the contact area is strictly below `area` (> 0): the report's
/// "displace the counterface upward until the restoring force exceeds the junction force", as a root solve.
double height_for_area_below(Gap& gap, double height, double area);

}  // namespace tribex::pstd
