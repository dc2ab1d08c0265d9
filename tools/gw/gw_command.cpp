// SPDX-License-Identifier: MIT
// `tribex gw`: the Greenwood-Williamson library from the command line (CSV output, nondimensional).
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "tools/common/command.hpp"
#include "tools/common/tabor.hpp"
#include "tools/common/subcommands.hpp"
#include "tools/common/text_file.hpp"
#include "contact/rough/gw_integrals.hpp"
#include "contact/rough/noncontact_attraction.hpp"
#include "tools/gw/gw_models.hpp"

namespace tribex::cli {
namespace {

using namespace tools::command;

const char* gw_usage =
    "usage: tribex gw SUBCOMMAND [options]   (nondimensional Greenwood-Williamson models, CSV output)\n"
    "  fn          F_n(t) = int_t^inf (s-t)^n phi(s) ds for n = 0, 1/2, 1, 3/2 (report Eq. 4.9)\n"
    "  curve       count, area and load vs t = d/sigma_s: continuous GW, a discrete population (Eq. 4.2)\n"
    "              and the DMT-adhesive load (Eqs. 4.10-4.12)\n"
    "  tangential  tangential force vs slip of the stick-until-capacity GW model (Fig. 4.11)\n"
    "  figures     the CSV data of Figs. 4.6, 4.7/4.8 and 4.11 into a folder (plot: tools/plot/gw_figures.py)\n"
    "Scales: area / (pi R sigma_s N), load / ((4/3) E* sqrt(R) sigma_s^{3/2} N), heights / sigma_s.\n"
    "tribex gw SUBCOMMAND --help for the options.\n";

struct Range {
  double lo, hi, step;
};

Range t_range(Args& a, double lo, double hi, double step) {
  Range r{a.real("--t-min", lo), a.real("--t-max", hi), a.real("--step", step)};
  if (!(r.lo >= -10 && r.hi <= 40 && r.lo < r.hi)) throw BadInput("--t-min/--t-max must satisfy -10 <= t-min < t-max <= 40");
  if (!(r.step > 0) || (r.hi - r.lo) / r.step > 1e6) throw BadInput("--step must be positive and give at most 1e6 points");
  return r;
}

std::vector<double> population(Args& a) {
  const long n = a.integer("--population", 0);
  const long seed = a.integer("--seed", 1);
  const bool stratified = a.flag("--stratified");
  if (n < 0 || n > 100000000) throw BadInput("--population must lie in 0 to 1e8");
  if (n == 0) return {};
  return stratified ? gw::stratified_gaussian_population(static_cast<std::size_t>(n))
                    : gw::gaussian_population(static_cast<std::size_t>(n), static_cast<std::uint64_t>(seed));
}

// The attraction of the non-contacting area in the tool's units (lengths / sigma_s, pressure / the load
// scale per summit density): the law's own class with W chosen so that 8 W / (3 z0) = S.
struct NoncontactOption {
  contact::NoncontactAttraction attraction;
};
NoncontactOption noncontact_option(Args& a) {
  const double scale = a.real("--noncontact-scale", 0.0), z0 = a.real("--noncontact-z0", 0.0);
  const double cutoff = a.real("--noncontact-cutoff", 200.0 * z0), sigma = a.real("--surface-sigma", 1.0);
  if (scale == 0.0 && z0 == 0.0) return {};
  if (!(scale > 0.0 && z0 > 0.0 && cutoff > z0 && sigma > 0.0))
    throw BadInput("--noncontact-scale and --noncontact-z0 must be positive, --noncontact-cutoff above z0, --surface-sigma positive");
  return {contact::NoncontactAttraction({3.0 * scale * z0 / 8.0, z0, cutoff}, sigma)};
}

int fn(const std::vector<std::string>& argv) {
  const char* usage =
      "usage: tribex gw fn [--t-min -3] [--t-max 8] [--step 0.1] [--csv FILE]\n"
      "Columns t, F_0, F_1/2, F_1, F_3/2 (closed forms for n = 0, 1; quadrature otherwise, ~1e-14 relative).\n";
  Args a(argv, "tribex gw fn", usage);
  if (a.answered_help()) return tools::exit_ok;
  const Range r = t_range(a, -3.0, 8.0, 0.1);
  const std::string csv = a.text("--csv", "");
  a.finish();
  std::ostringstream o;
  o << "t,F0,F1_2,F1,F3_2\n";
  char b[256];
  for (long i = 0; r.lo + static_cast<double>(i) * r.step <= r.hi + 1e-12; ++i) {
    const double t = r.lo + static_cast<double>(i) * r.step;
    std::snprintf(b, sizeof b, "%.6f,%.17g,%.17g,%.17g,%.17g\n", t, gw::gw_integral(0, t), gw::gw_integral(0.5, t),
                  gw::gw_integral(1, t), gw::gw_integral(1.5, t));
    o << b;
  }
  tools::write_text_output(csv, o.str());
  return tools::exit_ok;
}

int curve(const std::vector<std::string>& argv) {
  const char* usage =
      "usage: tribex gw curve [--t-min -3] [--t-max 4] [--step 0.05] [--population N [--seed S | --stratified]]\n"
      "                       [--beta B] [--z0 Z] [--csv FILE]\n"
      "Columns t, count, area, load of the continuous GW; with --population N also those of a discrete\n"
      "population of N Gaussian summit heights (random, seeded, or --stratified at the normal quantiles);\n"
      "with --beta the DMT applied load, beta = 3 pi W sqrt(R) / (2 E* sigma_s^{3/2}), and --z0 (units of\n"
      "sigma_s) adds the 3-9 attraction of the asperities out of contact. The adhesive load is DMT per asperity:\n"
      "it assumes each asperity's Tabor parameter mu_T = (2 beta/(3 pi))^(2/3)/z0 <= 0.3 and, with --z0, warns\n"
      "(one line on stderr) when it is larger (docs/theory.md 10.4).\n"
      "With --noncontact-scale S --noncontact-z0 Z [--noncontact-cutoff C] [--surface-sigma G] the column\n"
      "noncontact_load is the (DMT) load minus the attraction of the non-contacting area (docs/theory.md 10.8;\n"
      "the rough-surface law's option): S = (8 W / (3 z0)) / (eta (4/3) E* sqrt(R) sigma_s^{3/2}) the\n"
      "Lennard-Jones traction scale in load units per summit density, Z, C (default 200 Z) and G (the surface\n"
      "height deviation, default 1) in units of sigma_s; evaluated by quadrature.\n";
  Args a(argv, "tribex gw curve", usage, {"--stratified"});
  if (a.answered_help()) return tools::exit_ok;
  const Range r = t_range(a, -3.0, 4.0, 0.05);
  const auto pop = population(a);
  const double beta = a.real("--beta", 0.0), z0 = a.real("--z0", 0.0);
  const NoncontactOption nc = noncontact_option(a);
  const std::string csv = a.text("--csv", "");
  a.finish();
  if (beta < 0 || z0 < 0) throw BadInput("--beta and --z0 must be >= 0");
  if (beta > 0 && z0 > 0) {
    char where[120];
    std::snprintf(where, sizeof where, "beta = %g, z0 = %g sigma_s", beta, z0);
    const std::string w = tools::regime_warning(tools::AdhesionRegime::dmt, gw::asperity_tabor(beta, z0),
                                                "tribex gw curve (DMT asperities)", where,
                                                "the dmt_load columns overstate each asperity's pull-off");
    if (!w.empty()) std::fprintf(stderr, "%s\n", w.c_str());
  }
  std::ostringstream o;
  o << "t,count,area,load";
  if (!pop.empty()) o << ",discrete_count,discrete_area,discrete_load";
  if (beta > 0) o << ",dmt_load" << (pop.empty() ? "" : ",discrete_dmt_load");
  if (nc.attraction.active()) o << ",noncontact_load";
  o << "\n";
  char b[128];
  for (long i = 0; r.lo + static_cast<double>(i) * r.step <= r.hi + 1e-12; ++i) {
    const double t = r.lo + static_cast<double>(i) * r.step;
    const auto c = gw::continuous_gw(t);
    std::snprintf(b, sizeof b, "%.6f,%.12g,%.12g,%.12g", t, c.count, c.area, c.load);
    o << b;
    if (!pop.empty()) {
      const auto d = gw::discrete_gw(pop, t);
      std::snprintf(b, sizeof b, ",%.12g,%.12g,%.12g", d.count, d.area, d.load);
      o << b;
    }
    if (beta > 0) {
      std::snprintf(b, sizeof b, ",%.12g", gw::dmt_gw(t, beta, z0).load);
      o << b;
      if (!pop.empty()) {
        std::snprintf(b, sizeof b, ",%.12g", gw::dmt_gw_discrete(pop, t, beta, z0).load);
        o << b;
      }
    }
    if (nc.attraction.active()) {
      const double contact = beta > 0 ? gw::dmt_gw(t, beta, z0).load : c.load;
      std::snprintf(b, sizeof b, ",%.12g", contact - nc.attraction.evaluate_direct(t).pressure);
      o << b;
    }
    o << "\n";
  }
  tools::write_text_output(csv, o.str());
  return tools::exit_ok;
}

int tangential(const std::vector<std::string>& argv) {
  const char* usage =
      "usage: tribex gw tangential [--t 1] [--slip-max 3] [--points 301] [--population N [--seed S]] [--csv FILE]\n"
      "Tangential force / (tau* pi R sigma_s N) against slip / (pi tau* sqrt(R sigma_s) / (8 G*)) at separation\n"
      "t = d/sigma_s: each asperity sticks (Mindlin stiffness 8 G* a) until tau* pi R w, then slides.\n"
      "Full sliding gives F_1(t), i.e. tau* times the real contact area.\n";
  Args a(argv, "tribex gw tangential", usage, {"--stratified"});
  if (a.answered_help()) return tools::exit_ok;
  const double t = a.real("--t", 1.0), smax = a.real("--slip-max", 3.0);
  const long pts = a.integer("--points", 301);
  const auto pop = population(a);
  const std::string csv = a.text("--csv", "");
  a.finish();
  if (!(t >= -5 && t <= 8)) throw BadInput("--t must lie in [-5, 8]");
  if (!(smax > 0 && smax < 100)) throw BadInput("--slip-max must lie in (0, 100)");
  if (pts < 2 || pts > 1000000) throw BadInput("--points must lie in 2 to 1e6");
  std::ostringstream o;
  o << "slip,force" << (pop.empty() ? "" : ",discrete_force") << "\n";
  char b[128];
  for (long i = 0; i < pts; ++i) {
    const double s = smax * static_cast<double>(i) / static_cast<double>(pts - 1);
    std::snprintf(b, sizeof b, "%.8g,%.12g", s, gw::tangential_gw(t, s));
    o << b;
    if (!pop.empty()) {
      std::snprintf(b, sizeof b, ",%.12g", gw::tangential_gw_discrete(pop, t, s));
      o << b;
    }
    o << "\n";
  }
  tools::write_text_output(csv, o.str());
  return tools::exit_ok;
}

int figures(const std::vector<std::string>& argv) {
  const char* usage =
      "usage: tribex gw figures --out DIR [--seed 1] [--beta 0.2]\n"
      "Writes fig4_6.csv (discrete populations with 1, 10, 100, 1000 contacting asperities at t = 1.5, and\n"
      "the continuous curve), fig4_7_8.csv (Hertz and DMT GW) and fig4_11.csv (tangential, continuous and\n"
      "a discrete population of 100 contacting asperities) into DIR.\n";
  Args a(argv, "tribex gw figures", usage);
  if (a.answered_help()) return tools::exit_ok;
  const std::string out = a.text("--out", "");
  const long seed = a.integer("--seed", 1);
  const double beta = a.real("--beta", 0.2);
  a.finish();
  if (out.empty()) throw BadInput("tribex gw figures needs --out DIR");
  if (!(beta > 0)) throw BadInput("--beta must be positive");
  char b[160];
  // Fig. 4.6: a population of N summits such that N F_0(1.5) = 1, 10, 100, 1000 asperities touch at t = 1.5.
  // Each curve is normalised by its own N, so all tend to the continuous (F_1, F_3/2) curve as N grows.
  {
    std::ostringstream o;
    o << "population,contacting_at_t1.5,t,area,load\n";
    const double f0 = gw::gw_integral(0.0, 1.5);
    for (int k = 0; k < 4; ++k) {
      const double contacting = std::pow(10.0, k);
      const auto n = static_cast<std::size_t>(std::lround(contacting / f0));
      const auto pop = gw::gaussian_population(n, static_cast<std::uint64_t>(seed) + static_cast<std::uint64_t>(k));
      for (int i = 0; i <= 200; ++i) {
        const double t = 4.0 - 0.025 * i;
        const auto d = gw::discrete_gw(pop, t);
        std::snprintf(b, sizeof b, "%zu,%g,%.4f,%.10g,%.10g\n", n, contacting, t, d.area, d.load);
        o << b;
      }
    }
    for (int i = 0; i <= 200; ++i) {
      const double t = 4.0 - 0.025 * i;
      const auto c = gw::continuous_gw(t);
      std::snprintf(b, sizeof b, "continuous,inf,%.4f,%.10g,%.10g\n", t, c.area, c.load);
      o << b;
    }
    tools::write_text_output(out + "/fig4_6.csv", o.str());
  }
  {
    std::ostringstream o;
    o << "t,area,hertz_load,dmt_load,beta\n";
    for (int i = 0; i <= 300; ++i) {
      const double t = 4.0 - 0.02 * i;
      const auto h = gw::continuous_gw(t);
      std::snprintf(b, sizeof b, "%.4f,%.10g,%.10g,%.10g,%g\n", t, h.area, h.load, gw::dmt_gw(t, beta).load, beta);
      o << b;
    }
    tools::write_text_output(out + "/fig4_7_8.csv", o.str());
  }
  {
    std::ostringstream o;
    o << "slip,continuous,discrete\n";
    const double t = 1.0;
    const auto n = static_cast<std::size_t>(std::lround(100.0 / gw::gw_integral(0.0, t)));
    const auto pop = gw::gaussian_population(n, static_cast<std::uint64_t>(seed) + 10);
    // Each curve is normalised by its own full-sliding force tau* A (continuous F_1(t), discrete sum of w).
    const double a_discrete = gw::discrete_gw(pop, t).area;
    for (int i = 0; i <= 300; ++i) {
      const double s = 0.01 * i;
      std::snprintf(b, sizeof b, "%.4f,%.10g,%.10g\n", s, gw::tangential_gw(t, s) / gw::gw_integral(1.0, t),
                    gw::tangential_gw_discrete(pop, t, s) / a_discrete);
      o << b;
    }
    tools::write_text_output(out + "/fig4_11.csv", o.str());
  }
  std::printf("wrote %s/fig4_6.csv, fig4_7_8.csv, fig4_11.csv\n", out.c_str());
  return tools::exit_ok;
}

}  // namespace

int gw_command(const std::vector<std::string>& args) {
  return tools::run_subcommand(args, "tribex gw", gw_usage,
                               {{"fn", fn}, {"curve", curve}, {"tangential", tangential}, {"figures", figures}});
}

}  // namespace tribex::cli
