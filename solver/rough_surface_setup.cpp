// SPDX-License-Identifier: MIT
// `model = rough surface` in a contact interaction: the Greenwood-Williamson law
// (contact/models/rough_surface.hpp), tabulated once here, with its shear and search settings.
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "solver/contact_setup.hpp"
#include "solver/errors.hpp"
#include "solver/output/run_log.hpp"

namespace tribex::solver {
namespace {

// Summit file: one summit per line, `height, radius` in metres (comma or blanks), '#' comments and one
// optional header line of words (`height_m,radius_m`). Bad lines are a SetupError naming FILE:LINE.
void read_summit_file(const inputs::InteractionSpec& it, std::vector<double>& heights, std::vector<double>& radii) {
  std::ifstream in(it.summit_file);
  if (!in)
    throw SetupError(it.summit_file_where.str() + ": error: cannot open summit file '" + it.summit_file +
                     "'; give a path relative to the deck");
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
    const std::string where = it.summit_file + ":" + std::to_string(number) + ": error: ";
    if (!(row >> h >> r) || (row >> extra))
      throw SetupError(where + "expected two numbers 'height_m, radius_m' per line");
    if (!std::isfinite(h) || !(r > 0.0) || !std::isfinite(r))
      throw SetupError(where + "the summit radius must be a positive finite number (metres) and the height finite");
    heights.push_back(h);
    radii.push_back(r);
  }
  if (heights.empty())
    throw SetupError(it.summit_file_where.str() + ": error: summit file '" + it.summit_file + "' holds no summits");
}

}  // namespace

void rough_surface_model(const inputs::InteractionSpec& it, const inputs::ContactSpec& spec,
                         const contact::ContactSurface& master, contact::InteractionSettings& s,
                         std::vector<std::string>* report) {
  auto log = [&](const std::string& line) {
    if (report) report->push_back("  interaction " + it.name + ": " + line);
  };
  contact::RoughSurfaceParameters q;
  q.composite_modulus = it.composite_modulus;
  q.work_of_adhesion = it.work_of_adhesion;
  if (!it.summit_file.empty()) {
    read_summit_file(it, q.summit_heights, q.summit_radii);
    q.map_area = it.summit_map_area;
  } else {
    q.summit_density = it.summit_density;
    q.summit_radius = it.summit_radius;
    q.sigma_s = it.summit_height_deviation;
  }
  s.model = contact::InterfaceModel::rough_surface;
  s.rough = std::make_shared<const contact::RoughSurfaceLaw>(std::move(q));
  s.mean_plane_offset = it.mean_plane_offset;
  const auto& law = *s.rough;
  const auto& p = law.parameters();
  if (law.discrete())
    log(format("rough surface (discrete GW): %zu summits from %s on %.4g m^2 (%.4g /um^2), E* = %.4g Pa, W = %.4g J/m^2; "
               "summit heights measured from their mean, highest %.4g m",
               p.summit_heights.size(), it.summit_file.c_str(), p.map_area,
               static_cast<double>(p.summit_heights.size()) / p.map_area * 1e-12, p.composite_modulus, p.work_of_adhesion,
               law.contact_separation()));
  else
    log(format("rough surface (continuous GW, table t = d/sigma_s in [%g, %g] step %g, Hermite): eta = %.4g /um^2, "
               "R = %.4g m, sigma_s = %.4g m, E* = %.4g Pa, W = %.4g J/m^2 (DMT per asperity)",
               contact::RoughSurfaceLaw::table_t_min, contact::RoughSurfaceLaw::table_t_max,
               contact::RoughSurfaceLaw::table_spacing, p.summit_density * 1e-12, p.summit_radius, p.sigma_s,
               p.composite_modulus, p.work_of_adhesion));
  log(format("mean-plane separation d = gap + %.4g m; no asperity touches beyond d = %.4g m; no penalty contact "
             "(the GW pressure is the normal law); the springs A_I dp/dd bound the time step",
             s.mean_plane_offset, law.contact_separation()));
  // The search must capture every node whose d is below the contact separation.
  const double reach = law.contact_separation() - s.mean_plane_offset;
  const double margin = s.search_margin > 0 ? s.search_margin : master.mean_edge;
  if (margin < reach) {
    if (spec.search_margin)
      throw SetupError(spec.where.str() + ": error: 'search margin' " + format("%.4g m", margin) +
                       " is below the rough-surface reach " + format("%.4g m", reach) + " of interaction '" + it.name +
                       "' (contact separation minus 'mean plane offset'); raise 'search margin' to at least that");
    s.search_margin = reach;
    log(format("search margin raised from the mean face edge %.4g m to the rough-surface reach %.4g m", margin, reach));
  }
  if (!(it.junction_strength > 0.0)) {
    log("no 'junction strength': frictionless");
    return;
  }
  s.junction.strength = it.junction_strength;
  s.junction.reference_speed = it.junction_reference_speed.value_or(0.1);
  // The shear damper c_I = tau* (A_c/A_0) A_I / v_ref is weak where few asperities touch, so v_ref is not
  // raised at set-up (as the junction model does with the full tau*): its bound 2 m_eff / c_I enters
  // the stable time step at run time instead (ContactManager::stable_time_step).
  log(format("shear tau* (A_c/A_0) tanh(|v_t|/v_ref): tau* = %.4g Pa, v_ref = %.4g m/s%s; the damper bound "
             "2 m_eff / c_I enters the time step",
             s.junction.strength, s.junction.reference_speed, it.junction_reference_speed ? "" : " (default)"));
}

}  // namespace tribex::solver
