// SPDX-License-Identifier: MIT
#include "mesh/asperity_limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace tribex::mesh {
namespace {

std::string nm(double metres);

// The nearest 3-significant-digit value (in nm, as nm() prints it) strictly below (down) or above
// (up) a bound x > 0: the value read back from its printed text is checked, so a suggestion taken
// as printed passes the limit.
double rounded_past(double x, bool down) {
  if (!(x > 0.0)) return 0.0;
  const double x_nm = x * 1e9;
  const double unit = std::pow(10.0, std::floor(std::log10(x_nm)) - 2);
  double steps = down ? std::floor(x_nm / unit) : std::ceil(x_nm / unit);
  for (int guard = 0; guard < 4; ++guard) {
    const double v = std::stod(nm(steps * unit * 1e-9)) * 1e-9;
    if (down ? v < x : v > x) return v;
    steps += down ? -1.0 : 1.0;
  }
  return steps * unit * 1e-9;
}

std::string nm(double metres) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g nm", metres * 1e9);
  return b;
}

struct Report {
  std::vector<AsperityLimitViolation> out;
  void add(const char* key, const std::string& message) { out.push_back({key, message}); }
};

}  // namespace

double asperity_corner_sag(const AsperitySpec& s, double w) {
  const double r2 = 0.5 * w * w;  // the column corner is at r = w / sqrt(2)
  return s.paraboloid ? r2 / (2.0 * s.radius) : s.radius - std::sqrt(std::max(0.0, s.radius * s.radius - r2));
}

std::vector<AsperityLimitViolation> asperity_limit_violations(const AsperitySpec& s) {
  Report r;
  const struct {
    const char* key;
    double value;
  } sizes[] = {{"radius", s.radius},           {"element size", s.element_size},       {"tip width", s.tip_width},
               {"tip height", s.tip_height},   {"substrate width", s.substrate_width}, {"substrate depth", s.substrate_depth},
               {"fine half width", s.fine_half_width}, {"fine depth", s.fine_depth}};
  for (const auto& k : sizes)
    if (!(k.value > 0.0)) r.add(k.key, "must be positive, got " + nm(k.value));
  if (!r.out.empty()) return r.out;  // the limits below are formulas in these sizes

  if (!(s.grading_ratio >= 1.0 && s.grading_ratio <= 2.0))
    r.add("grading ratio", "must be in [1, 2], got " + std::to_string(s.grading_ratio) + "; nearest valid: " +
                               (s.grading_ratio < 1.0 ? "1" : "2"));
  if (!(s.gap >= 0.0)) r.add("gap", "must be >= 0, got " + nm(s.gap) + "; nearest valid: 0");

  // Sphere: the column corners (at w / sqrt(2) from the axis) within 0.9 R, so the bottom face is
  // not near-vertical there: w < 0.9 sqrt(2) R.
  double w = s.tip_width;
  const double w_max = 0.9 * std::sqrt(2.0) * s.radius;
  if (!s.paraboloid && !(w < w_max)) {
    w = rounded_past(w_max, true);
    r.add("tip width", "the column corners (at tip width / sqrt(2) = " + nm(s.tip_width / std::sqrt(2.0)) +
                           " from the axis) must stay within 0.9 R = " + nm(0.9 * s.radius) +
                           ": tip width < 0.9 sqrt(2) R = " + nm(w_max) + "; nearest valid: " + nm(w));
  }
  // The column must be taller than twice the sag of its bottom face at the corners.
  const double sag = asperity_corner_sag(s, w);
  if (!(sag < 0.5 * s.tip_height))
    r.add("tip height", "must exceed twice the sag of the bottom face at the column corners, 2 (" +
                            std::string(s.paraboloid ? "w^2/(4R)" : "R - sqrt(R^2 - w^2/2)") + ") = " + nm(2 * sag) +
                            " for tip width w = " + nm(w) + ", got " + nm(s.tip_height) +
                            "; nearest valid: " + nm(rounded_past(2 * sag, false)));
  // The uniformly fine square |x|, |y| <= fine half width lies inside the tip column and the substrate.
  const double fine_max = 0.5 * (s.tip_only ? w : std::min(w, s.substrate_width));
  if (!(s.fine_half_width < fine_max))
    r.add("fine half width", "must be below half the tip width" + std::string(s.tip_only ? "" : " and half the substrate width") +
                                 ", " + nm(fine_max) + (w != s.tip_width ? " with tip width " + nm(w) : "") + ", got " +
                                 nm(s.fine_half_width) + "; nearest valid: " + nm(rounded_past(fine_max, true)) +
                                 (s.tip_only ? "" : " (a longer fine strip of the substrate along x: 'fine x range')"));
  if (s.fine_x_range) {
    const double half = 0.5 * s.substrate_width, x0 = (*s.fine_x_range)[0], x1 = (*s.fine_x_range)[1];
    if (s.tip_only) r.add("fine x range", "refines the substrate, and 'substrate = none' has none; remove it");
    if (!(x0 <= 0.0 && x0 > -half))
      r.add("fine x range", "its start X0 must be in (-substrate width/2, 0] = (" + nm(-half) + ", 0], got " + nm(x0) +
                                "; nearest valid: " + (x0 > 0.0 ? std::string("0 nm") : nm(-rounded_past(half, true))));
    if (!(x1 >= 0.0 && x1 < half))
      r.add("fine x range", "its end X1 must be in [0, substrate width/2) = [0, " + nm(half) + "), got " + nm(x1) +
                                "; nearest valid: " + (x1 < 0.0 ? std::string("0 nm") : nm(rounded_past(half, true))) +
                                " (or a wider substrate: substrate width > 2 X1 = " + nm(2 * x1) + ")");
  }
  if (s.coating_thickness < 0.0 || (s.coating_thickness > 0.0 && s.coating_layers < 1))
    r.add("coating thickness", "must be >= 0 with at least one of 'coating layers'");
  if (!(s.coating_thickness < s.substrate_depth))
    r.add("coating thickness", "must be below the substrate depth " + nm(s.substrate_depth) + ", got " +
                                   nm(s.coating_thickness) + "; nearest valid: " +
                                   nm(rounded_past(s.substrate_depth, true)) + " (or a deeper substrate)");
  if (s.tip_only && s.quarter)
    r.add("symmetry", "a tip-only asperity (substrate = none) cannot be a quarter model (its symmetry planes need the "
                      "substrate); nearest valid: symmetry = none");
  return r.out;
}

}  // namespace tribex::mesh
