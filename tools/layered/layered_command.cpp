// SPDX-License-Identifier: MIT
// `tribex layered`: a sphere on bonded elastic layers over a half-space or a rigid base
// (docs/theory.md 11.4): a, delta, pressure and the coated study's f against P~, with A, b fitted.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "inputs/units.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/command.hpp"
#include "tools/common/csv_record.hpp"
#include "tools/common/json.hpp"
#include "tools/common/text_file.hpp"
#include "tools/layered/curve.hpp"

namespace tribex::layered {
namespace {

using namespace tools::command;

const char* usage =
    "usage: tribex layered --radius R --thickness H[,H2...] --layer-youngs E[,...] --layer-poisson NU[,...]\n"
    "         [--youngs 161GPa --poisson 0.23 | --rigid-indenter]\n"
    "         [--substrate-youngs 161GPa --substrate-poisson 0.23 | --rigid-base]\n"
    "         [--p-tilde LO,HI | --loads P1,P2,... | --p-tilde-file FILE.csv] [--points 100]\n"
    "         [--spacing log|linear|approach] [--fit LO,HI] [--pressure N] [-o DIR] [--no-plot]\n"
    "         [--nodes 24] [--hankel-per-panel 16] [--hankel-extent 40] [--check-convergence] [--json]\n"
    "Frictionless contact of an elastic sphere (radius R, --youngs/--poisson) on layers bonded to each other and\n"
    "to an elastic half-space (or a rigid base), from the surface down; exact Hankel-space compliance of the\n"
    "stack and the Abel-form integral equation with a smooth edge (docs/theory.md 11.4, tools/layered/README.md).\n"
    "Loads: P~ = P/(E*_top h_top^2) from LO to HI (default 0.02,1.59), log-spaced (default), linear in P~, or\n"
    "linear in the approach; or forces (--loads 1nN,10nN); or a CSV with a p_tilde column (e.g. an FE run's rows).\n"
    "f = a^2/(3PR/(4E_eff))^(2/3), 1/E_eff = 1/E*_indenter + 1/E*_top (report Eq. B.1), fitted as A P~^b over\n"
    "--fit LO,HI (default: every load). Writes DIR/layered.csv (P~, P, a, delta, f, p(0)), DIR/summary.json,\n"
    "DIR/pressure.csv (--pressure N radii per load) and DIR/layered.png (default DIR = layered_output).\n"
    "--check-convergence solves again with twice the nodes and Hankel points and prints the largest |df|.\n";

std::vector<double> required_list(Args& a, const std::string& name, inputs::Dimension d, const std::string& example) {
  auto v = a.list(name, d);
  if (v.empty()) throw BadInput("tribex layered: " + name + " is required (e.g. " + name + " " + example + ")");
  return v;
}

Stack parse_stack(Args& a) {
  const auto h = required_list(a, "--thickness", dim::length, "2nm");
  const auto e = required_list(a, "--layer-youngs", dim::pressure, "8GPa");
  const auto nu = required_list(a, "--layer-poisson", dim::none, "0.4");
  if (e.size() != h.size() || nu.size() != h.size())
    throw BadInput("tribex layered: --thickness, --layer-youngs and --layer-poisson need one value per layer (" +
                   std::to_string(h.size()) + ", " + std::to_string(e.size()) + " and " + std::to_string(nu.size()) + " given)");
  Stack s;
  for (std::size_t i = 0; i < h.size(); ++i) s.layers.push_back({h[i], {e[i], nu[i]}});
  const bool rigid = a.flag("--rigid-base");
  const auto es = a.quantity("--substrate-youngs", dim::pressure);
  const auto nus = a.real("--substrate-poisson");
  if (rigid && (es || nus))
    throw BadInput("tribex layered: --rigid-base takes no --substrate-youngs/--substrate-poisson (drop one or the other)");
  if (!rigid) s.substrate = Elastic{es.value_or(161e9), nus.value_or(0.23)};
  validate(s);
  return s;
}

Spacing parse_spacing(const std::string& s) {
  if (s == "log") return Spacing::log;
  if (s == "linear") return Spacing::linear;
  if (s == "approach") return Spacing::approach;
  throw BadInput("tribex layered: unknown --spacing '" + s + "' (use log, linear or approach)");
}

std::vector<double> range_of(const std::vector<double>& v, const std::string& name, std::vector<double> fallback) {
  if (v.empty()) return fallback;
  if (v.size() != 2 || !(v[0] > 0) || !(v[1] >= v[0]))
    throw BadInput("tribex layered: " + name + " takes LO,HI with 0 < LO <= HI (e.g. " + name + " 0.02,1.59)");
  return v;
}

std::string csv_text(const std::vector<CurvePoint>& pts, const std::string& about) {
  std::ostringstream o;
  o << "# tribex layered: " << about << "\n"
    << "# p_tilde = P/(E*_top h_top^2); f = a^2/(3PR/(4E_eff))^(2/3) (report Eq. B.1); center_pressure = p(r = 0)\n"
    << "p_tilde[-],load[nN],contact_radius[nm],approach[nm],f[-],center_pressure[GPa]\n";
  char buf[256];
  for (const auto& p : pts) {
    std::snprintf(buf, sizeof buf, "%.12g,%.12g,%.12g,%.12g,%.12g,%.9g\n", p.p_tilde, p.load * 1e9, p.radius * 1e9,
                  p.approach * 1e9, p.f, p.center_pressure * 1e-9);
    o << buf;
  }
  return o.str();
}

std::string pressure_text(Contact& c, const std::vector<double>& p_tilde, double scale, int radii) {
  std::ostringstream o;
  o << "# tribex layered: pressure profiles, one block of rows per load\n"
    << "p_tilde[-],r[nm],r_over_a[-],pressure[GPa]\n";
  double guess = 0;
  char buf[160];
  for (double pt : p_tilde) {
    if (guess == 0) guess = std::cbrt(3 * pt * scale * c.sphere_radius() / (4 * c.effective_modulus()));
    const auto s = c.sphere_at_load(pt * scale, guess);
    guess = s.radius;
    std::vector<double> r;
    for (int i = 0; i < radii; ++i) r.push_back(s.radius * i / radii);
    const auto p = c.pressure(s, r);
    for (int i = 0; i < radii; ++i) {
      std::snprintf(buf, sizeof buf, "%.9g,%.9g,%.6g,%.9g\n", pt, r[i] * 1e9, r[i] / s.radius, p[i] * 1e-9);
      o << buf;
    }
  }
  return o.str();
}

double max_f_difference(const std::vector<CurvePoint>& x, const std::vector<CurvePoint>& y) {
  double d = 0;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) d = std::max(d, std::abs(x[i].f - y[i].f));
  return d;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

void draw(const std::string& dir, const PowerFit& fit, const std::string& title) {
  std::string cmd = "/usr/bin/python3 ";
  cmd += shell_quote(TRIBEX_LAYERED_PLOT_SCRIPT);
  cmd += ' ';
  cmd += shell_quote(dir + "/layered.csv");
  cmd += " --out ";
  cmd += shell_quote(dir + "/layered.png");
  char buf[200];
  std::snprintf(buf, sizeof buf, " --A %.9g --b %.9g --fit %.9g,%.9g --title ", fit.A, fit.b, fit.lo, fit.hi);
  cmd += buf;
  cmd += shell_quote(title);
  if (std::system(cmd.c_str()) != 0)
    std::fprintf(stderr, "warning: %s/layered.png was not drawn (/usr/bin/python3 with matplotlib failed); the CSV is complete\n",
                 dir.c_str());
}

}  // namespace

int run(const std::vector<std::string>& argv) {
  Args a(argv, "tribex layered", usage, {"--rigid-indenter", "--rigid-base", "--no-plot", "--check-convergence", "--json"});
  if (a.answered_help()) return tools::exit_ok;
  const auto radius = a.quantity("--radius", dim::length);
  if (!radius || !(*radius > 0)) throw BadInput("tribex layered: --radius R > 0 is required (the sphere's radius, e.g. --radius 27nm)");
  const Stack stack = parse_stack(a);
  const bool rigid_tip = a.flag("--rigid-indenter");
  Elastic tip{a.quantity("--youngs", 161e9, dim::pressure), a.real("--poisson", 0.23)};
  if (rigid_tip) tip.youngs = std::numeric_limits<double>::infinity();
  if (!rigid_tip && (!(tip.youngs > 0) || !(tip.poisson > -1 && tip.poisson < 0.5)))
    throw BadInput("tribex layered: the sphere needs --youngs > 0 and -1 < --poisson < 0.5 (or --rigid-indenter)");
  Settings set;
  set.nodes = static_cast<int>(a.integer("--nodes", set.nodes));
  set.hankel_per_panel = static_cast<int>(a.integer("--hankel-per-panel", set.hankel_per_panel));
  set.hankel_extent = a.real("--hankel-extent", set.hankel_extent);
  if (set.nodes < 4 || set.nodes > 400 || set.hankel_per_panel < 4 || set.hankel_per_panel > 64 || !(set.hankel_extent >= 10))
    throw BadInput("tribex layered: --nodes 4..400, --hankel-per-panel 4..64 and --hankel-extent >= 10 (defaults 24, 16, 40)");
  const auto loads = a.list("--loads", dim::force);
  const auto file = a.text("--p-tilde-file");
  const auto range_text = a.list("--p-tilde", dim::none);
  const bool range_given = !range_text.empty();
  if ((!loads.empty()) + (file.has_value()) + range_given > 1)
    throw BadInput("tribex layered: give one of --p-tilde LO,HI, --loads and --p-tilde-file");
  const auto range = range_of(range_text, "--p-tilde", {0.02, 1.59});
  const int points = static_cast<int>(a.integer("--points", 100));
  const Spacing spacing = parse_spacing(a.text("--spacing", "log"));
  const auto fit_text = a.list("--fit", dim::none);
  range_of(fit_text, "--fit", {});  // checked before anything is computed
  const int pressure_radii = static_cast<int>(a.integer("--pressure", 0));
  if (pressure_radii < 0 || pressure_radii > 10000) throw BadInput("tribex layered: --pressure N takes 0..10000 radii per load");
  const std::string dir = a.text("-o", "layered_output");
  const bool plot = !a.flag("--no-plot"), check = a.flag("--check-convergence"), json = a.flag("--json");
  a.finish();

  const double scale = stack.top().plane_strain() * std::pow(stack.layers.front().thickness, 2);
  Contact contact(stack, tip, *radius, set);
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> p_tilde;
  if (!loads.empty()) {
    for (double p : loads) p_tilde.push_back(p / scale);
  } else if (file) {
    const auto rec = tools::CsvRecord::read(*file);
    rec.require_rows(1, "(one row per load; column p_tilde)");
    p_tilde = rec.column("p_tilde", dim::none);
  } else {
    p_tilde = p_tilde_list(contact, scale, range[0], range[1], points, spacing);
  }
  const auto curve = load_curve(contact, scale, p_tilde);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto fr = range_of(fit_text, "--fit", {curve.front().p_tilde, curve.back().p_tilde});
  const PowerFit fit = power_fit(curve, fr[0], fr[1]);
  double convergence = std::nan("");
  if (check) {
    Settings fine = set;
    fine.nodes *= 2;
    fine.hankel_per_panel *= 2;
    fine.hankel_extent *= 1.5;
    Contact c2(stack, tip, *radius, fine);
    convergence = max_f_difference(curve, load_curve(c2, scale, p_tilde));
  }
  std::filesystem::create_directories(dir);
  std::ostringstream about;
  about << stack.layers.size() << " layer(s), top h = " << stack.layers.front().thickness * 1e9 << " nm, E = "
        << stack.top().youngs * 1e-9 << " GPa; base ";
  if (stack.substrate) about << "elastic, E = " << stack.substrate->youngs * 1e-9 << " GPa"; else about << "rigid";
  about << "; R = " << *radius * 1e9 << " nm";
  tools::write_text_file(dir + "/layered.csv", csv_text(curve, about.str()));
  if (pressure_radii > 0) tools::write_text_file(dir + "/pressure.csv", pressure_text(contact, p_tilde, scale, pressure_radii));
  std::ostringstream js;
  using tools::json_number;
  js << "{\"loads\": " << curve.size() << ", \"p_tilde_min\": " << json_number(curve.front().p_tilde)
     << ", \"p_tilde_max\": " << json_number(curve.back().p_tilde) << ", \"fit_rows\": " << fit.rows
     << ", \"A\": " << json_number(fit.A) << ", \"b\": " << json_number(fit.b) << ", \"A_se\": " << json_number(fit.A_se)
     << ", \"b_se\": " << json_number(fit.b_se) << ", \"r2\": " << json_number(fit.r2) << ", \"rms_ln_f\": " << json_number(fit.rms)
     << ", \"fit_p_tilde\": [" << json_number(fit.lo) << ", " << json_number(fit.hi) << "]"
     << ", \"hankel_points\": " << contact.hankel_points() << ", \"nodes\": " << set.nodes
     << ", \"max_abs_df_refined\": " << (std::isnan(convergence) ? std::string("null") : json_number(convergence, 3))
     << ", \"seconds\": " << json_number(seconds, 3) << "}\n";
  tools::write_text_file(dir + "/summary.json", js.str());
  if (json) {
    std::fputs(js.str().c_str(), stdout);
  } else {
    std::printf("%s\n%zu loads, P~ %.4g-%.4g, a %.4g-%.4g nm, f %.6g-%.6g (%.3f s, %zu Hankel points, %d nodes)\n",
                about.str().c_str(), curve.size(), curve.front().p_tilde, curve.back().p_tilde, curve.front().radius * 1e9,
                curve.back().radius * 1e9, curve.front().f, curve.back().f, seconds, contact.hankel_points(), set.nodes);
    std::printf("fit f = A P~^b over P~ %.4g-%.4g (%d loads): A = %.6f +- %.6f, b = %.6f +- %.6f, R^2 = %.5f, rms ln f %.4f\n",
                fit.lo, fit.hi, fit.rows, fit.A, fit.A_se, fit.b, fit.b_se, fit.r2, fit.rms);
    if (check) std::printf("convergence: largest |f - f(2x nodes, 2x Hankel points, 1.5x extent)| = %.2e\n", convergence);
    std::printf("wrote %s/layered.csv, %s/summary.json%s\n", dir.c_str(), dir.c_str(), pressure_radii ? ", pressure.csv" : "");
  }
  if (plot) draw(dir, fit, about.str());
  return tools::exit_ok;
}

}  // namespace tribex::layered

namespace tribex::cli {
int layered_command(const std::vector<std::string>& args) { return layered::run(args); }
}  // namespace tribex::cli
