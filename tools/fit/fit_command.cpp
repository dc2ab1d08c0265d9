// SPDX-License-Identifier: MIT
// `tribex fit friction|synth`: junction strength tau* and work of adhesion W from AFM
// friction-vs-load data (report 3.3, Eq. 3.1 and Appendix C), with 1-sigma uncertainties and the
// parameter correlation, and synthetic data with known parameters to check the fit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "inputs/units.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/command.hpp"
#include "tools/common/csv_record.hpp"
#include "tools/common/subcommands.hpp"
#include "tools/common/fit_report.hpp"
#include "tools/common/panel_plot.hpp"
#include "tools/fit/friction_fit.hpp"
#include "tools/fit/regime.hpp"

namespace tribex::fit {
namespace {

using namespace tools::command;

const char* top_usage =
    "usage: tribex fit friction|synth ... (each with --help)\n"
    "  friction  fit tau* and W (and optionally alpha_p, the COS alpha or Ec) to friction-vs-load data\n"
    "  synth     write friction-vs-load data from a model with known parameters and seeded noise\n";

#define FIT_MODEL_OPTIONS                                                                                    \
  "model options (values take units: 27nm, 161GPa, 0.05J/m^2; plain numbers are SI):\n"                    \
  "  --model coated|dmt|jkr|cos|md   contact-area law (default coated = report Eq. 3.1)\n"                   \
  "  --radius R                      tip radius (required)\n"                                                \
  "  --youngs 161GPa --poisson 0.23  tip and substrate (Si); uncoated models use 1/E* = 2/Ebar\n"            \
  "  --reduced-modulus E*            E* for dmt/jkr/cos/md instead\n"                                        \
  "  coated: --coating-youngs 8GPa --coating-poisson 0.4 --coating-thickness 2nm\n"                          \
  "          --coating-table CSV (default: the repository's verification/coated/results.csv; ebar_c_over_ebar,A,b[,A_sigma,b_sigma],\n"     \
  "          interpolated in ln(Ebar_c/Ebar)) or --A A --b b; f = min(1, max(f_deep, A P~^b))\n"             \
  "  cos:    --alpha A (fixed; fitted when absent)     md: --lambda L | --z0 Z (lambda from W)\n"            \
  "  --z0 Z (default 0.3nm) also sets the Tabor parameter mu_T of the fit: dmt and coated assume DMT and\n"    \
  "          warn above mu_T 0.3, jkr assumes JKR and warns below 3; cos and md cover the transition\n"      \
  "  --pressure-dependent            tau = tau0 + alpha_p p: F = tau0 A + alpha_p int_A p dA\n"

const char* friction_usage =
    "usage: tribex fit friction DATA.csv --radius R [model options] [--fit-coating-modulus]\n"
    "         [--residual absolute|relative] [--json] [-o PLOT.png] [--no-plot]\n"
    "DATA.csv: columns normal_force and friction_force (or load and friction), force units in the header\n"
    "(normal_force[nN],friction_force[nN]); no unit = N. The CSV of `tribex friction-test static` points.\n"
    "Fits F = tau A(L + 2 pi R W) (report Eq. 3.1 for the coated model) by Levenberg-Marquardt and\n"
    "prints tau*, W with 1-sigma uncertainties, the correlation matrix and the pull-off load; draws\n"
    "the data and the fitted curve to PLOT.png (default DATA.png). --fit-coating-modulus frees Ec too:\n"
    "Eq. 3.1 then determines only tau/Ec^(2/3) (report 3.3), which the correlation shows.\n"
    "--residual relative fits ln F (noise proportional to F).\n" FIT_MODEL_OPTIONS;

const char* synth_usage =
    "usage: tribex fit synth -o OUT.csv --radius R --tau T --W W [model options] [--alpha-p A]\n"
    "         [--loads -5nN,30nN] [--points 30] [--noise 0.05] [--noise-kind relative|absolute] [--seed 1]\n"
    "Writes normal_force[nN],friction_force[nN] from the model plus Gaussian noise of --noise times F (relative)\n"
    "or times the largest F (absolute).\n" FIT_MODEL_OPTIONS;

FrictionSetup parse_setup(Args& a, const std::string& cmd) {
  FrictionSetup s;
  const std::string model = a.text("--model", "coated");
  const auto m = parse_area_model(model);
  if (!m) throw BadInput(cmd + ": unknown --model '" + model + "' (use coated, dmt, jkr, cos or md)");
  s.model = *m;
  const auto radius = a.quantity("--radius", dim::length);
  if (!radius) throw BadInput(cmd + ": --radius R is required (the tip radius, e.g. --radius 27nm)");
  s.radius = *radius;
  s.youngs = a.quantity("--youngs", s.youngs, dim::pressure);
  s.poisson = a.real("--poisson", s.poisson);
  s.reduced_modulus = a.quantity("--reduced-modulus", dim::pressure);
  s.coating_youngs = a.quantity("--coating-youngs", s.coating_youngs, dim::pressure);
  s.coating_poisson = a.real("--coating-poisson", s.coating_poisson);
  s.coating_thickness = a.quantity("--coating-thickness", s.coating_thickness, dim::length);
  const auto table = a.text("--coating-table");
  const auto A = a.real("--A");
  const auto b = a.real("--b");
  if (A.has_value() != b.has_value()) throw BadInput(cmd + ": give both --A and --b, or neither");
  if (A && table) throw BadInput(cmd + ": give --coating-table or --A/--b, not both");
  if (A) {
    if (!(*A > 0)) throw BadInput(cmd + ": --A must be > 0");
    s.area_law = AreaLawConstants{*A, *b, 0.0, 0.0};
  } else if (s.model == AreaModel::coated) {
    s.table = CoatingTable::read(table.value_or(TRIBEX_COATED_RESULTS));  // the repository's table, any working directory
  } else if (table) {
    throw BadInput(cmd + ": --coating-table applies to --model coated only");
  }
  s.md_lambda = a.real("--lambda");
  s.md_z0 = a.quantity("--z0", dim::length);
  s.cos_alpha = a.real("--alpha");
  s.pressure_dependent = a.flag("--pressure-dependent");
  return s;
}

Residual parse_residual(const std::string& text, const std::string& cmd, const std::string& option) {
  if (text == "absolute") return Residual::absolute;
  if (text == "relative") return Residual::relative;
  throw BadInput(cmd + ": " + option + " must be absolute or relative, not '" + text + "'");
}

std::vector<double> scaled(const std::vector<double>& v, double factor) {
  std::vector<double> out(v);
  for (double& x : out) x *= factor;
  return out;
}

void plot_fit(const std::string& png, const FrictionModel& model, const FrictionFit& fit,
              const std::vector<double>& load, const std::vector<double>& friction) {
  const double l_min = *std::min_element(load.begin(), load.end());
  const double l_max = *std::max_element(load.begin(), load.end());
  const double from = std::max(fit.pull_off_load, l_min - 0.05 * (l_max - l_min));
  const auto grid = load_ramp(from, l_max + 0.02 * (l_max - l_min), 200);
  std::vector<double> x = load, data = friction, curve(load.size(), NAN);
  std::vector<double> residual(load.size());
  const auto at_data = model.friction(fit.best, load);
  for (std::size_t i = 0; i < load.size(); ++i) residual[i] = friction[i] - (*at_data)[i];
  for (double l : grid) {
    const auto f = model.friction(fit.best, {l});
    x.push_back(l);
    data.push_back(NAN);
    curve.push_back(f ? f->front() : NAN);
  }
  char title[200];
  std::snprintf(title, sizeof title, "%s fit: tau = %.4g MPa, W = %.4g J/m^2", model_name(model.setup().model).c_str(),
                fit.best.tau / 1e6, fit.best.work_of_adhesion);
  tools::PlotPanel main{"normal force (nN)", "friction force (nN)", title,
                        {{"load", scaled(x, 1e9)}, {"data", scaled(data, 1e9)}, {"fit", scaled(curve, 1e9)}}};
  tools::PlotPanel res{"normal force (nN)", "data - fit (nN)", "residuals",
                       {{"load", scaled(load, 1e9)}, {"residual", scaled(residual, 1e9)}}};
  if (tools::write_plot(png, "tribex fit friction", {main, res})) std::fprintf(stderr, "plot: %s\n", png.c_str());
}

int friction_command(const std::vector<std::string>& argv) {
  const std::string cmd = "tribex fit friction";
  Args a(argv, cmd, friction_usage, {"--json", "--no-plot", "--pressure-dependent", "--fit-coating-modulus"});
  if (a.answered_help()) return tools::exit_ok;
  const std::string file = a.positional(0, "DATA.csv");
  FrictionSetup setup = parse_setup(a, cmd);
  setup.free_coating_modulus = a.flag("--fit-coating-modulus");
  const Residual residual = parse_residual(a.text("--residual", "absolute"), cmd, "--residual");
  const bool json = a.flag("--json");
  const bool no_plot = a.flag("--no-plot");
  const auto plot = a.text("-o");
  a.finish();
  const FrictionModel model(setup);

  const auto rec = tools::CsvRecord::read(file);
  const auto& load = rec.column("normal_force", dim::force);
  const auto& friction = rec.column("friction_force", dim::force);
  const std::size_t n_free = model.free_names().size();
  rec.require_rows(n_free + 2, "(to fit " + std::to_string(n_free) + " parameters with 2 degrees of freedom left)");
  for (std::size_t i = 0; i < rec.size(); ++i) {
    if (friction[i] < 0)
      throw BadInput(rec.where(i) + ": friction " + std::to_string(friction[i]) +
                     " N is negative (friction is half the trace-retrace difference, >= 0; check the sign convention)");
    if (residual == Residual::relative && !(friction[i] > 0))
      throw BadInput(rec.where(i) + ": --residual relative needs friction > 0 (drop the zero rows or use absolute)");
  }
  std::vector<double> distinct(load);
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  if (distinct.size() < 3) throw BadInput(file + ": the loads take fewer than 3 distinct values (vary the load)");

  const FrictionFit fit = fit_friction(model, load, friction, residual);
  const auto& names = fit.names;

  tools::FitReport r;
  r.command = "fit friction";
  r.text = {{"file", file}, {"model", model_name(setup.model)},
            {"residual", residual == Residual::absolute ? "absolute" : "relative"}};
  std::string joined;
  for (const auto& n : names) joined += (joined.empty() ? "" : ",") + n;
  r.text.emplace_back("parameters", joined);
  r.add(names[0], fit.best.tau, fit.sigma(names[0]), "Pa", setup.pressure_dependent ? "tau0 of tau = tau0 + alpha_p p" : "junction strength tau*");
  r.add("W", fit.best.work_of_adhesion, fit.sigma("W"), "J/m^2", "work of adhesion");
  if (setup.pressure_dependent) r.add("alpha_p", fit.best.pressure_coefficient, fit.sigma("alpha_p"), "", "pressure coefficient");
  if (setup.model == AreaModel::cos) {
    r.add("cos_alpha", fit.best.cos_alpha, setup.cos_alpha ? -1 : fit.sigma("cos_alpha"), "", setup.cos_alpha ? "fixed" : "COS transition parameter");
    r.add("lambda", model.lambda(fit.best), -1, "", "-0.924 ln(1 - 1.02 alpha)");
  }
  if (setup.model == AreaModel::maugis_dugdale) r.add("lambda", model.lambda(fit.best), -1, "", "Maugis parameter");
  if (setup.model == AreaModel::coated) {
    r.add("Ec", fit.best.coating_youngs, setup.free_coating_modulus ? fit.sigma("Ec") : -1, "Pa",
          setup.free_coating_modulus ? "fitted (see correlation)" : "given");
    const double ebar_c = fit.best.coating_youngs / (1 - setup.coating_poisson * setup.coating_poisson);
    const auto law = model.area_law(fit.best.coating_youngs);
    r.add("ebar_c_over_ebar", ebar_c / model.plane_strain_modulus(), -1, "");
    r.add("A", law.A, law.A_sigma > 0 ? law.A_sigma : -1, "", setup.area_law ? "given" : "from the coating table");
    r.add("b", law.b, law.b_sigma > 0 ? law.b_sigma : -1, "", setup.area_law ? "given" : "from the coating table");
    // F ~ tau A where f = A P~^b is not clipped, so A's own uncertainty moves tau by the same fraction;
    // kept apart from the statistical sigma (it is systematic: one table for all the data).
    if (law.A_sigma > 0)
      r.add("tau_systematic_from_A", fit.best.tau * law.A_sigma / law.A, -1, "Pa", "tau A_sigma/A, not in tau's sigma");
    double pt_lo = INFINITY, pt_hi = 0;
    for (double l : load) {
      const double pt = (l + 2 * std::numbers::pi * setup.radius * fit.best.work_of_adhesion) /
                        (ebar_c * setup.coating_thickness * setup.coating_thickness);
      pt_lo = std::min(pt_lo, pt);
      pt_hi = std::max(pt_hi, pt);
    }
    r.add("p_tilde_min", pt_lo, -1, "", "P/(Ebar_c h_c^2); the report's fits cover 0.02-2");
    r.add("p_tilde_max", pt_hi, -1, "");
    if (setup.free_coating_modulus) {
      const auto c = tau_over_ec_power(fit, 2.0 / 3.0);
      r.add("tau_over_Ec^(2/3)", c.value, c.sigma, "Pa^(1/3)", "report 3.3's combination");
      const auto v = tau_over_ec_valley(fit);
      r.add("valley_exponent_k", v.exponent, -1, "", "best-determined tau/Ec^k (~2/3 + b, less as A, b vary with Ec)");
      r.add("tau_over_Ec^k", v.value, v.sigma, "Pa^(1-k)", "the combination the data determine best");
    }
  }
  r.add("pull_off_load", fit.pull_off_load, -1, "N", "of the fitted model");
  const RegimeCheck regime = check_regime(model, fit.best);
  r.text.emplace_back("regime", regime.regime ? tools::regime_text(*regime.regime) : std::string("transition (any mu_T)"));
  r.add("tabor", regime.tabor, -1, "", "mu_T = (R W^2/(E*^2 z0^3))^(1/3); " + regime.basis);
  r.add("rms_residual", fit.lm.rms_residual, -1, residual == Residual::absolute ? "N" : "", "");
  r.add("points", static_cast<double>(load.size()), -1, "");
  std::vector<std::vector<double>> corr;
  for (Eigen::Index i = 0; i < fit.lm.correlation.rows(); ++i) {
    corr.emplace_back();
    for (Eigen::Index j = 0; j < fit.lm.correlation.cols(); ++j) corr.back().push_back(fit.lm.correlation(i, j));
  }
  r.tables.emplace_back("correlation", corr);
  if (setup.model == AreaModel::dmt && !setup.pressure_dependent) {
    const auto sc = dmt_shortcut(load, friction, setup.radius, model.reduced_modulus());
    r.add("shortcut_tau", sc.tau, sc.tau_sigma, "Pa", "DMT F^(3/2)-vs-L line (docs/theory.md 9.2)");
    r.add("shortcut_W", sc.work_of_adhesion, sc.work_sigma, "J/m^2", "DMT F^(3/2)-vs-L line");
  }

  if (json) {
    std::printf("%s\n", r.json().c_str());
  } else {
    r.print_table(stdout);
    std::printf("correlation (%s):\n", joined.c_str());
    for (const auto& row : corr) {
      for (double v : row) std::printf(" %8.4f", v);
      std::printf("\n");
    }
    if (setup.free_coating_modulus) {
      std::printf("note: corr(%s, Ec) = %.4f: with Ec free the data fix only a combination tau/Ec^k (report 3.3:\n"
                  "      k = 2/3 when b = 0; here k = %.3f); the separate sigmas of %s and Ec measure the length\n"
                  "      of that valley, not %s or Ec.\n",
                  names[0].c_str(), fit.correlation(names[0], "Ec"), tau_over_ec_valley(fit).exponent,
                  names[0].c_str(), names[0].c_str());
    }
  }
  if (!regime.warning.empty()) std::fprintf(stderr, "%s\n", regime.warning.c_str());
  if (!no_plot) plot_fit(plot.value_or(tools::default_plot_path(file)), model, fit, load, friction);
  return tools::exit_ok;
}

int synth_command(const std::vector<std::string>& argv) {
  const std::string cmd = "tribex fit synth";
  Args a(argv, cmd, synth_usage, {"--pressure-dependent"});
  if (a.answered_help()) return tools::exit_ok;
  const auto out = a.text("-o");
  const FrictionSetup setup = parse_setup(a, cmd);
  const auto tau = a.quantity("--tau", dim::pressure);
  const auto w = a.quantity("--W", dim::energy_per_area);
  const double alpha_p = a.real("--alpha-p", 0.0);
  const auto loads = a.list("--loads", dim::force);
  const long points = a.integer("--points", 30);
  const double noise = a.real("--noise", 0.05);
  const Residual kind = parse_residual(a.text("--noise-kind", "relative"), cmd, "--noise-kind");
  const long seed = a.integer("--seed", 1);
  a.finish();
  if (!out) throw BadInput(cmd + ": -o OUT.csv is required");
  if (!tau || !w) throw BadInput(cmd + ": --tau and --W are required (e.g. --tau 100MPa --W 0.05J/m^2)");
  if (points < 2 || noise < 0) throw BadInput(cmd + ": need --points >= 2 and --noise >= 0");
  // Bounded before allocating (issue 54, item 12; tools/fit/README.md): 1e7 points are a 240 MB CSV and
  // about 100 s of the md model.
  if (points > 10'000'000)
    throw BadInput(cmd + ": --points " + std::to_string(points) + " is more than the limit of 10000000 (a 240 MB CSV); "
                   "give fewer points");
  const FrictionModel model(setup);
  FrictionParams p = model.defaults(*tau, *w);
  p.pressure_coefficient = alpha_p;
  const std::vector<double> range = loads.empty() ? std::vector<double>{-5e-9, 30e-9} : loads;
  if (range.size() != 2) throw BadInput(cmd + ": --loads takes FROM,TO (e.g. -5nN,30nN)");
  const auto l = load_ramp(range[0], range[1], static_cast<int>(points));
  if (range[0] < model.pull_off_load(p))
    throw BadInput(cmd + ": --loads starts below the model's pull-off load " + std::to_string(model.pull_off_load(p) * 1e9) +
                   " nN (raise the first load)");
  const auto f = synth_friction(model, p, l, noise, kind, static_cast<std::uint64_t>(seed));
  tools::CsvRecord(*out, {{"normal_force", {l, "nN"}}, {"friction_force", {f, "nN"}}}).write(*out);
  std::fprintf(stderr, "wrote %s\n", out->c_str());
  return tools::exit_ok;
}

}  // namespace
}  // namespace tribex::fit

namespace tribex::cli {

int fit_command(const std::vector<std::string>& args) {
  using namespace tribex::fit;
  return tools::run_subcommand(args, "tribex fit", top_usage, {{"friction", friction_command}, {"synth", synth_command}});
}

}  // namespace tribex::cli
