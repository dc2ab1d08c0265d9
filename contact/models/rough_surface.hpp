// SPDX-License-Identifier: MIT
// The grid-scale rough-surface (Greenwood-Williamson) interaction law (report Section 4.3-4.5;
// docs/theory.md 10.3-10.5). A slave node stands for a patch A_I of a rough surface whose summits face a
// flat counterface (the master) at the mean-plane separation d (measured from the mean of the summit
// heights, docs/theory.md 10.2). Per unit nominal area A_0:
//
//   continuous Gaussian summits (density eta, radius R, height deviation sigma_s, t = d / sigma_s):
//     N/A_0   = eta F_0(t)                                                       (Eq. 4.1)
//     A_c/A_0 = pi eta R sigma_s F_1(t)
//     p       = eta [ (4/3) E* sqrt(R) sigma_s^{3/2} F_{3/2}(t) - 2 pi W R F_0(t) ]  (Hertz, DMT Eq. 4.10)
//   discrete population (summit i: height z_i above the mean summit height, radius R_i, w_i = z_i - d):
//     p = (1/A_map) sum_{w_i > 0} [ (4/3) E* sqrt(R_i) w_i^{3/2} - 2 pi W R_i ],
//     A_c/A_0 = (1/A_map) sum pi R_i w_i,   N/A_0 = (count of w_i > 0) / A_map        (Eq. 4.2, 4.11).
//
// p > 0 is compressive. DMT adhesion acts only on contacting asperities (the report's Eq. 4.10
// form, no attraction across a gap). The shear traction is the junction law with tau* times the
// real-area fraction: tau = -tau* (A_c/A_0) tanh(|v_t|/v_ref) v_t/|v_t|.
//
// Speed: the continuous law is tabulated once at start-up on a uniform grid in t with F_n and their
// exact derivatives dF_n/dt = -n F_{n-1} (dF_0/dt = -phi) and evaluated by cubic Hermite interpolation
// (interpolation error below 1e-7 of the value on the table range, tests/contact/rough_surface_test);
// the discrete law sums the summits in contact directly (heights sorted, so the loop stops at the
// first summit below d: cost proportional to the contacts, meant for few-asperity populations).
#pragma once

#include <algorithm>
#include <vector>

#include "contact/rough/noncontact_attraction.hpp"

namespace tribex::contact {

struct RoughSurfaceParameters {
  double summit_density = 0.0;     // eta, 1/m^2 (continuous)
  double summit_radius = 0.0;      // R, m (continuous)
  double sigma_s = 0.0;            // standard deviation of the summit heights, m (continuous)
  double composite_modulus = 0.0;  // E*, Pa
  double work_of_adhesion = 0.0;   // W, J/m^2 (0: Hertz asperities)
  // Discrete population (when not empty): heights (m, any datum: they are re-measured from their
  // mean), radii (m) and the area of the map they were found on (m^2).
  std::vector<double> summit_heights, summit_radii;
  double map_area = 0.0;
  // Attraction of the non-contacting area (continuous only; rough/noncontact_attraction.hpp), on when
  // noncontact_z0 > 0: the Lennard-Jones law with W, this z0 and cut-off, over Gaussian surface
  // heights of deviation surface_sigma (0: sigma_s).
  double noncontact_z0 = 0.0;      // m
  double noncontact_cutoff = 0.0;  // h_c, m (> z0)
  double surface_sigma = 0.0;      // m
};

/// The law at one separation, per unit nominal area.
struct RoughSurfaceState {
  double pressure = 0.0;           // apparent pressure p (Pa, > 0 compressive) = Hertz part - adhesion
  double adhesion = 0.0;           // the DMT pull 2 pi W R per contacting asperity, per nominal area (Pa, >= 0)
  double area_fraction = 0.0;      // A_c / A_0
  double contact_density = 0.0;    // asperity contacts per nominal area N/A_0, 1/m^2
  double stiffness = 0.0;          // -dp/dd, Pa/m (Hertz part; >= 0) + |slope| of the non-contact term, for the stable time step
  double noncontact = 0.0;         // attraction of the non-contacting area (Pa, >= 0; included in `adhesion`)
};

class RoughSurfaceLaw {
 public:
  RoughSurfaceLaw() = default;
  /// Builds the table (continuous) or sorts the population (discrete); throws std::invalid_argument
  /// on non-positive parameters.
  explicit RoughSurfaceLaw(RoughSurfaceParameters parameters);

  /// p, A_c/A_0, N/A_0 and the stiffness at mean-plane separation d (m): table or direct sum.
  RoughSurfaceState evaluate(double d) const;
  /// The same from the GW integrals F_n(t) evaluated directly (continuous) or the summit sum
  /// (discrete): the reference the table is checked against; too slow for the step loop.
  RoughSurfaceState evaluate_direct(double d) const;

  /// Beyond this separation no asperity touches: t_max sigma_s, or the highest summit.
  double contact_separation() const { return contact_separation_; }
  /// Beyond this separation p = 0: the contact separation, or the reach of the non-contact attraction.
  double reach() const { return noncontact_.active() ? std::max(contact_separation_, noncontact_.reach()) : contact_separation_; }
  const NoncontactAttraction& noncontact() const { return noncontact_; }
  bool discrete() const { return !heights_.empty(); }
  const RoughSurfaceParameters& parameters() const { return parameters_; }
  /// Dimensional factors of the continuous law: N/A_0 = count F_0, A_c/A_0 = area F_1,
  /// p = hertz F_3/2 - adhesion F_0 (Pa), t = d inverse_sigma.
  struct Scales {
    double count = 0.0, area = 0.0, hertz = 0.0, adhesion = 0.0, inverse_sigma = 0.0;
  };
  /// Nondimensional table range and spacing of the continuous law (t = d / sigma_s).
  static constexpr double table_t_min = -8.0, table_t_max = 6.0, table_spacing = 0.02;

 private:
  RoughSurfaceParameters parameters_;
  double contact_separation_ = 0.0;
  Scales scales_;
  // continuous: values and t-derivatives of F_0, F_1, F_3/2 at t_k = t_min + k h
  std::vector<double> f0_, f1_, f32_, df0_, df1_, df32_;
  // discrete: heights above the mean summit height (descending) and the matching radii
  std::vector<double> heights_, radii_;
  NoncontactAttraction noncontact_;
  RoughSurfaceState contact_part(double d) const;  // the continuous GW law from the table
};

}  // namespace tribex::contact
