// SPDX-License-Identifier: MIT
#include "contact/laws/rough_surface.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace tribex::contact {
namespace {

// Summit file: one summit per line, `height, radius` in metres (comma or blanks), '#' comments and one
// optional header line of words (`height_m,radius_m`). Bad lines are a LawError naming FILE:LINE.
void read_summit_file(const std::string& file, std::vector<double>& heights, std::vector<double>& radii) {
  std::ifstream in(file);
  if (!in) throw LawError("summit file", "cannot open summit file '" + file + "'; give a path relative to the deck");
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    for (char& c : line)
      if (c == ',' || c == ';' || c == '\t' || c == '\r') c = ' ';
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) continue;
    if (heights.empty() && number <= 2 && std::isalpha(static_cast<unsigned char>(first[0]))) continue;  // header
    std::istringstream row(line);
    double h = 0.0, r = 0.0;
    std::string extra;
    const std::string where = file + ":" + std::to_string(number) + ": error: ";
    if (!(row >> h >> r) || (row >> extra))
      throw LawError("summit file", where + "expected two numbers 'height_m, radius_m' per line", true);
    if (!std::isfinite(h) || !(r > 0.0) || !std::isfinite(r))
      throw LawError("summit file", where + "the summit radius must be a positive finite number (metres) and the height finite",
                     true);
    heights.push_back(h);
    radii.push_back(r);
  }
  if (heights.empty()) throw LawError("summit file", "summit file '" + file + "' holds no summits");
}

// Explicit junction shear tau A_I on the node (docs/theory.md 7.1-7.2), added to f (force on the slave
// node); v_t is the tangential part of v_slave - sum_a N_a v_a (relative to the master point).
void add_shear(const ContactPoint& p, const JunctionLaw& law, PassView& view, double f[3]) {
  double vr[3] = {0.0, 0.0, 0.0};
  if (view.v) {
    for (int i = 0; i < 3; ++i) {
      vr[i] = view.v[3 * p.node + i];
      for (int a = 0; a < 4; ++a) vr[i] -= p.shape[a] * view.v[3 * p.face_nodes[a] + i];
    }
  }
  const double vn = vr[0] * p.normal[0] + vr[1] * p.normal[1] + vr[2] * p.normal[2];
  double vt[3], tau[3];
  for (int i = 0; i < 3; ++i) vt[i] = vr[i] - vn * p.normal[i];
  junction_traction(vt, law, tau);
  const double sign = view.primary ? 1.0 : -1.0;
  double power = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double ft = view.factor * tau[i] * p.area;
    f[i] += ft;
    view.friction_of(p.node)[i] += sign * ft;
    power += ft * vt[i];
  }
  ContactTotals& totals = view.totals_of(p.node);
  totals.friction_power += std::abs(power);
  totals.junction_capacity += view.factor * law.strength * p.area;
}

}  // namespace

RoughSurface RoughSurface::make(const KeyValues& v) {
  RoughSurfaceParameters q;
  q.composite_modulus = v.get("composite modulus", 0.0);
  q.work_of_adhesion = v.get("work of adhesion", 0.0);
  RoughSurface r;
  r.summit_file = v.path("summit file");
  if (!r.summit_file.empty()) {
    read_summit_file(r.summit_file, q.summit_heights, q.summit_radii);
    q.map_area = v.get("summit map area", 0.0);
  } else {
    q.summit_density = v.get("summit density", 0.0);
    q.summit_radius = v.get("summit radius", 0.0);
    q.sigma_s = v.get("summit height deviation", 0.0);
  }
  if (const auto z0 = v.find("noncontact equilibrium separation")) {
    q.noncontact_z0 = *z0;
    q.noncontact_cutoff = v.get("noncontact cutoff", default_noncontact_cutoff_in_z0 * *z0);
    q.surface_sigma = v.get("surface height deviation", q.sigma_s);
  }
  r.law = std::make_shared<const RoughSurfaceLaw>(std::move(q));
  r.mean_plane_offset = v.get("mean plane offset", 0.0);
  r.shear.strength = v.get("junction strength", 0.0);
  r.shear.reference_speed = v.get("junction reference speed", 0.1);
  return r;
}

std::string RoughSurface::describe() const {
  const auto& p = law->parameters();
  char text[900];
  int n = 0;
  if (law->discrete())
    n = std::snprintf(text, sizeof text,
                      "rough surface (discrete GW): %zu summits from %s on %.4g m^2 (%.4g /um^2), E* = %.4g Pa, W = %.4g "
                      "J/m^2; summit heights measured from their mean, highest %.4g m",
                      p.summit_heights.size(), summit_file.c_str(), p.map_area,
                      static_cast<double>(p.summit_heights.size()) / p.map_area * 1e-12, p.composite_modulus,
                      p.work_of_adhesion, law->contact_separation());
  else
    n = std::snprintf(text, sizeof text,
                      "rough surface (continuous GW, table t = d/sigma_s in [%g, %g] step %g, Hermite): eta = %.4g /um^2, "
                      "R = %.4g m, sigma_s = %.4g m, E* = %.4g Pa, W = %.4g J/m^2 (DMT per asperity)",
                      RoughSurfaceLaw::table_t_min, RoughSurfaceLaw::table_t_max, RoughSurfaceLaw::table_spacing,
                      p.summit_density * 1e-12, p.summit_radius, p.sigma_s, p.composite_modulus, p.work_of_adhesion);
  n += std::snprintf(text + n, sizeof text - static_cast<std::size_t>(n),
                     "; mean-plane separation d = gap + %.4g m; no asperity touches beyond d = %.4g m; no penalty "
                     "contact (the GW pressure is the normal law); the springs A_I dp/dd bound the time step",
                     mean_plane_offset, law->contact_separation());
  std::string line = text;
  if (const NoncontactAttraction& a = law->noncontact(); a.active())
    line += format_line("; attraction of the non-contacting area: W = %.4g J/m^2, z0 = %.4g m, h_c = %.4g m, surface "
                        "heights sigma = %.4g m, zero beyond d = %.4g m",
                        a.law().work, a.law().z0, a.law().cutoff, a.sigma(), a.reach());
  if (!(shear.strength > 0.0)) return line + "; no 'junction strength': frictionless";
  // The shear damper c_I = tau* (A_c/A_0) A_I / v_ref is weak where few asperities touch, so v_ref is
  // not raised: its bound 2 m_eff / c_I enters the stable time step at run time.
  return line + format_line("; shear tau* (A_c/A_0) tanh(|v_t|/v_ref): tau* = %.4g Pa, v_ref = %.4g m/s; the damper "
                            "bound 2 m_eff / c_I enters the time step",
                            shear.strength, shear.reference_speed);
}

void RoughSurface::at_point(const ContactPoint& p, PassView& view) const {
  const double d = p.gap + mean_plane_offset;
  if (d >= law->reach()) return;
  const RoughSurfaceState s = law->evaluate(d);
  ContactTotals& totals = view.totals_of(p.node);
  const double fn_mag = view.factor * s.pressure * p.area;
  double f[3];
  for (int i = 0; i < 3; ++i) f[i] = fn_mag * p.normal[i];
  // Totals split like the other models: the Hertz (repulsive) part and the DMT pull.
  const double pull = view.factor * s.adhesion * p.area;
  totals.compressive_force += fn_mag + pull;
  totals.adhesive_force += pull;
  totals.nominal_area += view.factor * p.area;
  totals.real_area += view.factor * p.area * s.area_fraction;
  totals.asperity_contacts += view.factor * p.area * s.contact_density;
  totals.max_penetration = std::max(totals.max_penetration, -p.gap);
  if (s.contact_density > 0.0) view.count_contact(p, true);
  if (shear.strength > 0.0 && s.area_fraction > 0.0) {
    JunctionLaw on_real_area = shear;
    on_real_area.strength *= s.area_fraction;  // tau* A_c / A_0: junction friction on the real area
    add_shear(p, on_real_area, view, f);
  }
  view.apply(p, f);
  // Explicit stability between the node and the face point (m_eff as for the penalty): the normal
  // spring k_I = A_I dp/dd needs dt < 2 sqrt(m_eff / k_I), the shear damper c_I = tau* (A_c/A_0) A_I / v_ref
  // (its slope at zero slip, docs/theory.md 7.3) needs dt < 2 m_eff / c_I.
  const double k_spring = view.factor * s.stiffness * p.area;
  const double c_damper = view.factor * shear.strength * s.area_fraction * p.area / shear.reference_speed;
  if (k_spring > 0.0 || c_damper > 0.0) {
    const double m_eff = view.effective_mass(p);
    double& stable_dt = view.stable_dt_of(p.node);
    if (k_spring > 0.0) stable_dt = std::min(stable_dt, 2.0 * std::sqrt(m_eff / k_spring));
    if (c_damper > 0.0) stable_dt = std::min(stable_dt, 2.0 * m_eff / c_damper);
  }
}

}  // namespace tribex::contact
