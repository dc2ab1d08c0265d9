// SPDX-License-Identifier: MIT
// docs/theory.md 6.7.6 (normalisation), 8.2-8.4 (the analytic neighbours).
#include "tools/adhesion/report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "tools/common/json.hpp"
#include "tools/fit/maugis_dugdale.hpp"

namespace tribex::adhesion {

Scales scales_of(const Problem& pb) {
  Scales s;
  const double w = pb.law.law.work, z0 = pb.law.law.z0, r = pb.radius, k = 4 * pb.e_star / 3;
  s.work = pb.law.captured_work();
  if (!(s.work > 0)) return s;
  s.load = M_PI * s.work * r;
  s.radius = std::cbrt(M_PI * s.work * r * r / k);
  s.approach = std::cbrt(M_PI * M_PI * s.work * s.work * r / (k * k));
  s.tabor = std::cbrt(r * w * w / (pb.e_star * pb.e_star * z0 * z0 * z0));
  s.lambda = 2 * 16 * w / (9 * std::sqrt(3.0) * z0) * std::cbrt(r / (M_PI * s.work * k * k));
  return s;
}

namespace {
std::string bar(double v, double scale) {
  if (!(scale > 0)) return "nan";
  char b[40];
  std::snprintf(b, sizeof b, "%.10g", v / scale);
  return b;
}
}  // namespace

std::string curve_csv(const Curve& c, const Problem& pb, const std::string& about) {
  const Scales s = scales_of(pb);
  std::ostringstream o;
  o << "# tribex adhesion-curve: " << about << "\n"
    << "# branch 0: control the central gap (down to g* = 0.2 z0); 1: control rho, the radius where g = g*;"
       " approach 0 = undeformed surfaces touching (h = z0); load compressive positive\n"
    << "# normalised with the captured work W_c (docs/theory.md 6.7.6): load_bar = P/(pi W_c R),"
       " a_bar = a (K/(pi W_c R^2))^(1/3), approach_bar = delta (K^2/(pi^2 W_c^2 R))^(1/3), K = 4E*/3\n"
    << "branch[-],approach[m],load[N],contact_radius[m],compressive_radius[m],bonded_radius[m],zone_radius[m],central_gap[m],min_gap[m],rings[-],"
       "approach_over_z0[-],load_bar[-],a_bar[-],approach_bar[-]\n";
  char b[400];
  for (const auto& p : c.points) {
    std::snprintf(b, sizeof b, "%d,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%.6g,%d,%.10g,", p.branch, p.approach, p.load,
                  p.contact_radius, p.compressive_radius, p.bonded_radius, p.zone_radius, p.central_gap, p.min_gap, p.rings, p.approach / pb.law.law.z0);
    o << b << bar(p.load, s.load) << ',' << bar(p.contact_radius, s.radius) << ',' << bar(p.approach, s.approach) << '\n';
  }
  return o.str();
}

// DMT (8.2): P = a^3 - 2, delta = a^2; JKR (8.3): P = a^3 - sqrt(6 a^3), delta = a^2 - (2/3) sqrt(6a);
// MD (8.4): Eqs. 1-3 at lambda.
std::string limits_csv(const Scales& s, double max_a_bar) {
  std::ostringstream o;
  char b[300];
  std::snprintf(b, sizeof b, "# analytic neighbours, normalised as docs/theory.md 8.4 with W_c; Maugis-Dugdale at lambda = %.6g\n",
                s.lambda);
  o << b << "a_bar[-],dmt_load_bar[-],dmt_approach_bar[-],jkr_load_bar[-],jkr_approach_bar[-],md_load_bar[-],md_approach_bar[-]\n";
  const fit::MaugisDugdale md(s.lambda > 0 ? s.lambda : 1.0);
  for (int i = 0; i <= 400; ++i) {
    const double a = 0.02 + (max_a_bar - 0.02) * i / 400.0;
    const auto m = md.at_radius(a);
    const double md_delta = a * a - 4.0 / 3.0 * md.lambda() * a * std::sqrt(m.m * m.m - 1);
    std::snprintf(b, sizeof b, "%.8g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", a, a * a * a - 2, a * a,
                  a * a * a - std::sqrt(6 * a * a * a), a * a - 2.0 / 3.0 * std::sqrt(6 * a), m.p_bar, md_delta);
    o << b;
  }
  return o.str();
}

namespace {
std::string marker_json(const Marker& m, const Scales& s) {
  using tools::json_number;
  if (!m.found) return "null";
  std::ostringstream o;
  o << "{\"approach_m\": " << json_number(m.approach) << ", \"load_N\": " << json_number(m.load)
    << ", \"contact_radius_m\": " << json_number(m.contact_radius)
    << ", \"compressive_radius_m\": " << json_number(m.compressive_radius) << ", \"bonded_radius_m\": " << json_number(m.bonded_radius)
    << ", \"zone_radius_m\": " << json_number(m.zone_radius)
    << ", \"load_bar\": "
    << (s.load > 0 ? json_number(m.load / s.load) : "null") << ", \"approach_bar\": "
    << (s.approach > 0 ? json_number(m.approach / s.approach) : "null") << "}";
  return o.str();
}
}  // namespace

std::string summary_json(const Curve& c, const Problem& pb, double seconds) {
  using tools::json_number;
  const Scales s = scales_of(pb);
  double max_pen = 0;
  for (const auto& p : c.points) max_pen = std::max(max_pen, -p.min_gap);
  std::ostringstream o;
  o << "{\"radius_m\": " << json_number(pb.radius) << ", \"e_star_Pa\": " << json_number(pb.e_star)
    << ", \"work_J_m2\": " << json_number(pb.law.law.work) << ", \"z0_m\": " << json_number(pb.law.law.z0)
    << ", \"cutoff_m\": " << json_number(pb.law.law.cutoff) << ", \"captured_work_J_m2\": " << json_number(s.work)
    << ", \"tabor\": " << json_number(s.tabor) << ", \"maugis_lambda\": " << json_number(s.lambda)
    << ", \"penalty_Pa_m\": " << json_number(pb.law.penalty) << ", \"points\": " << c.points.size()
    << ", \"max_rings\": " << c.max_rings << ", \"max_penetration_m\": " << json_number(max_pen)
    << ",\n \"pull_off_load_control\": " << marker_json(c.pull_off, s)
    << ",\n \"jump_out_displacement_control\": " << marker_json(c.jump_out, s)
    << ",\n \"jump_in_displacement_control\": " << marker_json(c.jump_in, s);
  if (s.lambda > 0) {
    const fit::MaugisDugdale md(s.lambda);
    o << ",\n \"maugis_dugdale_pull_off_bar\": " << json_number(md.pull_off().p_bar);
  }
  o << ",\n \"seconds\": " << json_number(seconds, 3) << "}\n";
  return o.str();
}

}  // namespace tribex::adhesion
