// SPDX-License-Identifier: MIT
// `tribex friction-test calibrate|static|dynamic|synth`: the data reduction of the report's
// Section 2 (nanotractor friction tests). Each subcommand reads a CSV record (record.hpp), fits
// its model and prints a table (plus a PNG next to the input or at -o) or, with --json, one
// JSON object of the fitted quantities with their 1-sigma uncertainties.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "inputs/units.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/command.hpp"
#include "tools/common/subcommands.hpp"
#include "tools/common/json.hpp"
#include "tools/friction_test/calibration.hpp"
#include "tools/friction_test/dynamic_friction.hpp"
#include "tools/common/panel_plot.hpp"
#include "tools/common/csv_record.hpp"
#include "tools/common/fit_report.hpp"
#include "tools/friction_test/static_friction.hpp"
#include "tools/friction_test/synth.hpp"

namespace tribex::friction_test {
namespace {

using namespace tools::command;

const char* top_usage =
    "usage: tribex friction-test calibrate|static|dynamic|synth ... (each with --help)\n"
    "Friction-test data reduction of the nanotractor tests (report Section 2):\n"
    "  calibrate  load-spring constant from a ringdown record (Eq. 2.4) and/or folded-spring geometry\n"
    "  static     mu_s and adhesion from a clamp-voltage ramp (Eqs. 2.2-2.3)\n"
    "  dynamic    F_d, damping and mu_d from post-slip oscillation records (Fig. 2.10-2.11)\n"
    "  synth      write a synthetic record with known parameters and seeded noise\n";

const char* calibrate_usage =
    "usage: tribex friction-test calibrate [FILE] [--mass 2.25ug] [--mass-uncertainty 0.15ug]\n"
    "         [--width W --length L --thickness T --youngs-modulus E [--folds 4]] [--json] [-o PLOT.png]\n"
    "FILE: CSV with columns time[s] and position[unit], a free ringdown, or frequency[Hz] and\n"
    "amplitude[unit], a driven resonance curve (fits X = (F0/m)/sqrt((w0^2-w^2)^2 + (2 sigma w)^2)). Fits\n"
    "x = x_eq + exp(-sigma t)(a cos wd t + b sin wd t); k = m w0^2 (Eq. 2.4), w0^2 = wd^2 + sigma^2,\n"
    "with the mass uncertainty propagated. Geometry options add the folded-flexure constant\n"
    "k = (folds/2) E T W^3 / L^3. Values take units (2.25ug, 1.8um, 164.8GPa); plain numbers are SI.\n";

const char* static_usage =
    "usage: tribex friction-test static FILE --stiffness K [--stiffness-uncertainty dK]\n"
    "         --gap G --area A [--mass M] [--kz KZ --z Z] [--zero-position X0] [--min-jump 0.5um]\n"
    "         [--foot-area AF] [--json] [-o PLOT.png]\n"
    "FILE: CSV with position[unit] and either voltage[V] (clamp voltage) or normal_force[unit].\n"
    "Slip events are jumps larger than --min-jump toward the spring zero X0. Before each jump the\n"
    "spring force F_s = K |x - X0| balances static friction at F_N = eps0 A V^2/(2 G^2) + M g - KZ Z\n"
    "(Eq. 2.3; a normal_force column is taken as F_N). Fits F_s = mu_s F_N + mu_s F_adh (Eq. 2.2).\n"
    "A FILE with normal_force and friction_force columns (no position) is a list of reduced points\n"
    "(e.g. steady sliding per load): the line is fitted through them directly; --stiffness is not needed.\n"
    "--foot-area reports the adhesion per area.\n";

const char* dynamic_usage =
    "usage: tribex friction-test dynamic FILE [FILE...] (--stiffness K | --mass M)\n"
    "         [--stiffness-uncertainty dK | --mass-uncertainty dM] [--normal-force F1,F2,...]\n"
    "         [--foot-area AF] [--json] [-o PLOT.png]\n"
    "FILE: CSV with time[s] and position[unit] from the slip on (~50 samples per cycle). Fits\n"
    "m x'' + c x' + k (x - x_eq) = -F_d sign(x') (exact piecewise solution, sticks at rest) and\n"
    "reports F_d, c, Q and the rms residual; with --normal-force (one per FILE), mu_d = F_d/F_N,\n"
    "and for 3 or more records the load line F_d = mu_d F_N + mu_d F_adh (Fig. 2.11).\n";

const char* synth_usage =
    "usage: tribex friction-test synth ringdown|dynamic|static -o FILE.csv [--noise 10nm] [--seed 1]\n"
    "  ringdown/dynamic: [--mass 2.25ug] [--stiffness 0.38] [--damping C] [--friction-force FD]\n"
    "                    [--static-force FS] [--release 5um] [--cycles 12] [--samples-per-cycle 50]\n"
    "  static: [--stiffness 4.5] [--mu-s 0.31] [--mu-d 0.28] [--adhesion-force FA] [--gap 2um]\n"
    "          [--area 0.24mm^2] [--start-position 40um] [--volts-start 100] [--volts-step 0.1]\n"
    "Writes a record from the models with known parameters plus Gaussian position noise.\n";

void emit(const tools::FitReport& r, bool json) {
  if (json) {
    std::printf("%s\n", r.json().c_str());
  } else {
    r.print_table(stdout);
  }
}

std::vector<double> to_nm(const std::vector<double>& v) {
  std::vector<double> out(v);
  for (double& x : out) x *= 1e9;
  return out;
}

std::vector<double> times_ms(const std::vector<double>& v) {
  std::vector<double> out(v);
  for (double& x : out) x *= 1e3;
  return out;
}

void plot_trace(const std::string& png, const std::string& title, const std::vector<double>& t,
                const std::vector<double>& x, const std::vector<double>& fit) {
  std::vector<double> residual(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) residual[i] = (x[i] - fit[i]) * 1e9;
  tools::PlotPanel trace{"time (ms)", "position (nm)", "data and fit", {{"t", times_ms(t)}, {"data", to_nm(x)}, {"fit", to_nm(fit)}}};
  tools::PlotPanel res{"time (ms)", "residual (nm)", "data - fit", {{"t", times_ms(t)}, {"residual", residual}}};
  if (tools::write_plot(png, title, {trace, res})) std::fprintf(stderr, "plot: %s\n", png.c_str());
}

// ---------------------------------------------------------------- calibrate
int calibrate(const std::vector<std::string>& argv) {
  Args a(argv, "tribex friction-test calibrate", calibrate_usage, {"--json"});
  if (a.answered_help()) return tools::exit_ok;
  const bool json = a.flag("--json");
  const double mass = a.quantity("--mass", 2.25e-9, dim::mass);
  const double mass_sigma = a.quantity("--mass-uncertainty", mass == 2.25e-9 ? 0.15e-9 : 0.0, dim::mass);
  const auto width = a.quantity("--width", dim::length);
  const auto length = a.quantity("--length", dim::length);
  const auto thickness = a.quantity("--thickness", dim::length);
  const auto youngs = a.quantity("--youngs-modulus", dim::pressure);
  const long folds = a.integer("--folds", 4);
  const auto plot = a.text("-o");
  const auto file = a.optional_positional(0);
  a.finish();
  const bool geometry = width || length || thickness || youngs;
  if (geometry && !(width && length && thickness && youngs))
    throw BadInput("tribex friction-test calibrate: the folded-spring constant needs all of --width, --length, "
                   "--thickness and --youngs-modulus");
  if (!file && !geometry)
    throw BadInput("tribex friction-test calibrate: give a ringdown FILE and/or the spring geometry (see --help)");
  if (mass <= 0 || mass_sigma < 0) throw BadInput("tribex friction-test calibrate: --mass must be > 0 and its uncertainty >= 0");
  if (folds < 1) throw BadInput("tribex friction-test calibrate: --folds must be >= 1");

  tools::FitReport r;
  r.command = "calibrate";
  if (geometry) {
    if (*width <= 0 || *length <= 0 || *thickness <= 0 || *youngs <= 0)
      throw BadInput("tribex friction-test calibrate: geometry and modulus must be > 0");
    r.add("stiffness_geometry", folded_spring_stiffness(*youngs, *thickness, *width, *length, static_cast<int>(folds)),
          -1, "N/m", "(folds/2) E t w^3 / L^3");
  }
  if (file && tools::CsvRecord::read(*file).has("frequency")) {
    const tools::CsvRecord rec = tools::CsvRecord::read(*file);
    const auto& f_hz = rec.column("frequency", dim::rate);
    const auto& amp = rec.column("amplitude", dim::length);
    rec.require_increasing("frequency");
    rec.require_rows(10, "for a resonance fit");
    std::vector<double> w(f_hz);
    for (double& v : w) v *= 2 * std::numbers::pi;
    const ResonanceFit f = fit_resonance(w, amp, *file);
    const Stiffness k = stiffness_from_frequency(f.omega0, f.omega0_sigma, mass, mass_sigma);
    r.text.push_back({"file", *file});
    r.add("omega0", f.omega0, f.omega0_sigma, "rad/s", "undamped natural frequency");
    r.add("frequency", f.omega0 / (2 * std::numbers::pi), f.omega0_sigma / (2 * std::numbers::pi), "Hz");
    r.add("decay_rate", f.sigma, f.sigma_sigma, "1/s", "sigma = c/(2m)");
    r.add("quality_factor", f.quality, f.quality_sigma, "", "omega0 / (2 sigma)");
    r.add("mass", mass, mass_sigma, "kg", "input");
    r.add("stiffness", k.value, k.sigma, "N/m", "k = m omega0^2 (Eq. 2.4)");
    r.add("rms_residual", f.rms_residual, -1, "m");
    emit(r, json);
    if (!json || plot) {
      std::vector<double> fit(w.size());
      for (std::size_t i = 0; i < w.size(); ++i) fit[i] = f.amplitude(w[i]) * 1e9;
      tools::PlotPanel curve{"frequency (Hz)", "amplitude (nm)", "resonance curve and fit", {{"f", f_hz}, {"data", to_nm(amp)}, {"fit", fit}}};
      const std::string png = plot.value_or(tools::default_plot_path(*file));
      if (tools::write_plot(png, "resonance: " + *file, {curve})) std::fprintf(stderr, "plot: %s\n", png.c_str());
    }
    return tools::exit_ok;
  }
  if (file) {
    const tools::CsvRecord rec = tools::CsvRecord::read(*file);
    const auto& t = rec.column("time", dim::time);
    const auto& x = rec.column("position", dim::length);
    rec.require_increasing("time");
    rec.require_rows(20, "for a ringdown fit");
    const RingdownFit f = fit_ringdown(t, x, *file);
    const Stiffness k = stiffness_from_frequency(f.omega0, f.omega0_sigma, mass, mass_sigma);
    r.text.push_back({"file", *file});
    r.add("omega_d", f.omega_d, f.omega_d_sigma, "rad/s", "damped natural frequency");
    r.add("decay_rate", f.sigma, f.sigma_sigma, "1/s", "sigma = c/(2m)");
    r.add("omega0", f.omega0, f.omega0_sigma, "rad/s", "sqrt(omega_d^2 + sigma^2)");
    r.add("frequency", f.omega0 / (2 * std::numbers::pi), f.omega0_sigma / (2 * std::numbers::pi), "Hz");
    r.add("quality_factor", f.quality, f.quality_sigma, "", "omega0 / (2 sigma)");
    r.add("mass", mass, mass_sigma, "kg", "input");
    r.add("stiffness", k.value, k.sigma, "N/m", "k = m omega0^2 (Eq. 2.4)");
    r.add("damping", 2 * mass * f.sigma, 2 * mass * f.sigma * std::hypot(mass_sigma / mass, f.sigma_sigma / f.sigma), "N s/m",
          "c = 2 m sigma");
    r.add("x_eq", f.x_eq, f.x_eq_sigma, "m", "rest position");
    r.add("rms_residual", f.rms_residual, -1, "m");
    if (!json || plot) {
      std::vector<double> fit(t.size());
      for (std::size_t i = 0; i < t.size(); ++i) fit[i] = f.position(t[i]);
      emit(r, json);
      plot_trace(plot.value_or(tools::default_plot_path(*file)), "ringdown: " + *file, t, x, fit);
      return tools::exit_ok;
    }
  }
  emit(r, json);
  return tools::exit_ok;
}

// The intercept, F_adh = intercept / slope and, given the foot area, the adhesion pressure F_adh / A of a load
// line (the static and the dynamic report).
void add_adhesion(tools::FitReport& r, const FrictionLine& line, const std::string& intercept_note,
                  std::optional<double> foot_area) {
  r.add("intercept", line.intercept, line.intercept_sigma, "N", intercept_note);
  r.add("adhesion_force", line.adhesion_force, line.adhesion_force_sigma, "N", "intercept / slope");
  if (foot_area && *foot_area > 0)
    r.add("adhesion_pressure", line.adhesion_force / *foot_area, line.adhesion_force_sigma / *foot_area, "Pa",
          "F_adh / foot area (1 nN/um^2 = 1000 Pa)");
}

// ---------------------------------------------------------------- static
int static_friction(const std::vector<std::string>& argv) {
  Args a(argv, "tribex friction-test static", static_usage, {"--json"});
  if (a.answered_help()) return tools::exit_ok;
  const bool json = a.flag("--json");
  const auto stiffness = a.quantity("--stiffness", dim::stiffness);
  const double stiffness_sigma = a.quantity("--stiffness-uncertainty", 0.0, dim::stiffness);
  ClampLoad clamp;
  const auto gap = a.quantity("--gap", dim::length);
  const auto area = a.quantity("--area", dim::area);
  clamp.mass = a.quantity("--mass", 0.0, dim::mass);
  clamp.kz = a.quantity("--kz", 0.0, dim::stiffness);
  clamp.z = a.quantity("--z", 0.0, dim::length);
  const double x_zero = a.quantity("--zero-position", 0.0, dim::length);
  const double min_jump = a.quantity("--min-jump", 0.5e-6, dim::length);
  const auto foot_area = a.quantity("--foot-area", dim::area);
  const auto plot = a.text("-o");
  const std::string file = a.positional(0, "FILE");
  a.finish();
  const std::string cmd = "tribex friction-test static";
  if (min_jump <= 0) throw BadInput(cmd + ": --min-jump must be > 0");

  const tools::CsvRecord rec = tools::CsvRecord::read(file);
  // Points already reduced (normal_force and friction_force columns, e.g. one steady-sliding FE run per
  // load, inputs/examples/clamp_friction): the Eq. 2.2 line through them, no slip detection.
  const bool points = rec.has("friction_force") && rec.has("normal_force") && !rec.has("position");
  if (!points && !rec.has("position")) {
    std::string have;
    for (const auto& n : rec.names()) have += (have.empty() ? "" : ",") + n;
    throw BadInput(file + ":1: missing column 'friction_force' (reduced points: normal_force, friction_force) or "
                   "'position' (a ramp record, with --stiffness); the header has: " + have);
  }
  if (!points && (!stiffness || *stiffness <= 0))
    throw BadInput(cmd + ": --stiffness K (N/m, > 0) is required: the load-spring constant");
  const std::vector<double> x = points ? std::vector<double>(rec.size(), 0.0) : rec.column("position", dim::length);
  std::vector<double> fn(rec.size());
  if (points) {
    fn = rec.column("normal_force", dim::force);
  } else if (rec.has("normal_force")) {
    fn = rec.column("normal_force", dim::force);
  } else if (rec.has("voltage")) {
    if (!gap || !area || *gap <= 0 || *area <= 0)
      throw BadInput(cmd + ": a voltage record needs --gap and --area (> 0) for the parallel-plate clamp force");
    clamp.gap = *gap;
    clamp.electrode_area = *area;
    const auto& v = rec.voltage("voltage");
    for (std::size_t i = 0; i < v.size(); ++i) fn[i] = clamp.normal_force(v[i]);
  } else {
    rec.column("voltage", dim::none);  // throws the missing-column message
  }
  if (rec.has("time")) rec.require_increasing("time");
  std::vector<SlipEvent> events;
  if (points) {
    const auto& fs = rec.column("friction_force", dim::force);
    for (std::size_t i = 0; i < fs.size(); ++i) events.push_back({i, 0.0, 0.0, fn[i], 0.0, fs[i]});
  } else {
    rec.require_rows(4, "for a static friction ramp");
    events = detect_slips(x, fn, *stiffness, x_zero, min_jump);
  }
  StaticFit f = fit_static(std::move(events), file, min_jump);
  // The spring constant scales every F_s: its relative error adds to mu_s (F_adh = intercept/slope is free of it).
  const double mu_sigma =
      points ? f.line.mu_sigma : std::hypot(f.line.mu_sigma, f.line.mu * stiffness_sigma / *stiffness);
  tools::FitReport r;
  r.command = "static";
  r.text.push_back({"file", file});
  r.add("slip_events", static_cast<double>(f.events.size()), -1, "");
  r.add("mu_s", f.line.mu, mu_sigma, "", "slope of Eq. 2.2");
  add_adhesion(r, f.line, "mu_s F_adh", foot_area);
  r.add("correlation", f.line.correlation, -1, "", "intercept-slope");
  r.add("rms_residual", f.line.rms_residual, -1, "N");
  std::vector<std::vector<double>> rows;
  for (const auto& e : f.events) rows.push_back({e.normal_force, e.friction_force, e.position, e.jump, e.load_resolution});
  r.tables.push_back({"slip_events_columns_normal_force_friction_force_position_jump_load_resolution", rows});
  if (!json) {
    r.print_table(stdout);
    std::printf("\n%12s %14s %14s %12s\n", "row", "F_N (N)", "F_s (N)", "jump (nm)");
    for (const auto& e : f.events)
      std::printf("%12s %14.6g %14.6g %12.1f\n", rec.where(e.row).substr(file.size() + 1).c_str(), e.normal_force,
                  e.friction_force, e.jump * 1e9);
  } else {
    emit(r, true);
  }
  if (!json || plot) {
    std::vector<double> fn_uN(fn), ev_n, ev_s, fit_s;
    for (double& v : fn_uN) v *= 1e6;
    for (const auto& e : f.events) {
      ev_n.push_back(e.normal_force * 1e6);
      ev_s.push_back(e.friction_force * 1e6);
      fit_s.push_back((f.line.intercept + f.line.mu * e.normal_force) * 1e6);
    }
    // Reduced points have no position record: one panel, the points and the line through them.
    std::vector<tools::PlotPanel> panels;
    if (!points) {
      std::vector<double> before(fn.size(), NAN);
      for (const auto& e : f.events) before[e.row] = x[e.row] * 1e9;
      panels.push_back({"normal force F_N (µN)", "position (nm)", "record; points before each slip",
                        {{"F_N", fn_uN}, {"position", to_nm(x)}, {"before slip", before}}});
    }
    panels.push_back({"normal force F_N (µN)", points ? "friction force F (µN)" : "static friction F_s (µN)",
                      "Eq. 2.2 fit", {{"F_N", ev_n}, {points ? "points" : "slip events", ev_s}, {"fit mu_s", fit_s}}});
    char title[160];
    std::snprintf(title, sizeof title, "static friction: mu_s = %.4f ± %.4f, F_adh = %.4g ± %.2g µN", f.line.mu, mu_sigma,
                  f.line.adhesion_force * 1e6, f.line.adhesion_force_sigma * 1e6);
    const std::string png = plot.value_or(tools::default_plot_path(file));
    if (tools::write_plot(png, title, panels)) std::fprintf(stderr, "plot: %s\n", png.c_str());
  }
  return tools::exit_ok;
}

// ---------------------------------------------------------------- dynamic
int dynamic_friction(const std::vector<std::string>& argv) {
  Args a(argv, "tribex friction-test dynamic", dynamic_usage, {"--json"});
  if (a.answered_help()) return tools::exit_ok;
  const std::string cmd = "tribex friction-test dynamic";
  const bool json = a.flag("--json");
  Calibration cal;
  const auto k = a.quantity("--stiffness", dim::stiffness);
  const auto m = a.quantity("--mass", dim::mass);
  cal.stiffness_sigma = a.quantity("--stiffness-uncertainty", 0.0, dim::stiffness);
  cal.mass_sigma = a.quantity("--mass-uncertainty", 0.0, dim::mass);
  const std::vector<double> loads = a.list("--normal-force", dim::force);
  const auto foot_area = a.quantity("--foot-area", dim::area);
  const auto plot = a.text("-o");
  std::vector<std::string> files;
  for (std::size_t i = 0; i < a.positional_count(); ++i) files.push_back(*a.optional_positional(i));
  a.finish();
  if (files.empty()) throw BadInput(cmd + ": missing FILE (see --help)");
  if (k.has_value() == m.has_value())
    throw BadInput(cmd + ": give exactly one of --stiffness (N/m) or --mass (kg) to turn the fit into forces");
  if (k) {
    if (*k <= 0) throw BadInput(cmd + ": --stiffness must be > 0");
    cal.stiffness = *k;
  } else {
    if (*m <= 0) throw BadInput(cmd + ": --mass must be > 0");
    cal.mass = *m;
  }
  if (!loads.empty() && loads.size() != files.size())
    throw BadInput(cmd + ": --normal-force has " + std::to_string(loads.size()) + " value(s) for " +
                   std::to_string(files.size()) + " file(s); give one load per FILE, in order");

  tools::FitReport r;
  r.command = "dynamic";
  std::vector<DynamicFit> fits;
  std::vector<std::vector<double>> rows;
  std::vector<tools::PlotPanel> panels;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const tools::CsvRecord rec = tools::CsvRecord::read(files[i]);
    const auto& t = rec.column("time", dim::time);
    const auto& x = rec.column("position", dim::length);
    rec.require_increasing("time");
    rec.require_rows(30, "for a dynamic-friction fit");
    fits.push_back(fit_dynamic(t, x, cal, files[i]));
    const DynamicFit& f = fits.back();
    rows.push_back({loads.empty() ? NAN : loads[i], f.friction_force, f.friction_force_sigma, f.damping, f.damping_sigma,
                    f.rms_residual});
    if (!json || plot) {
      std::vector<double> residual(x.size());
      for (std::size_t j = 0; j < x.size(); ++j) residual[j] = (x[j] - f.model[j]) * 1e9;
      char title[160];
      std::snprintf(title, sizeof title, "%s: F_d = %.4g N, c = %.3g N s/m, rms %.3g nm", files[i].c_str(), f.friction_force,
                    f.damping, f.rms_residual * 1e9);
      panels.push_back({"time (ms)", "position (nm)", title, {{"t", times_ms(t)}, {"data", to_nm(x)}, {"fit", to_nm(f.model)}}});
      if (files.size() == 1)
        panels.push_back({"time (ms)", "residual (nm)", "data - fit", {{"t", times_ms(t)}, {"residual", residual}}});
    }
  }
  if (files.size() == 1) {
    const DynamicFit& f = fits.front();
    r.text.push_back({"file", files.front()});
    r.add("friction_force", f.friction_force, f.friction_force_sigma, "N", "F_d");
    r.add("damping", f.damping, f.damping_sigma, "N s/m", "c");
    if (!loads.empty() && loads.front() > 0)
      r.add("mu_d", f.friction_force / loads.front(), f.friction_force_sigma / loads.front(), "", "F_d / F_N");
    r.add("omega0", f.oscillator.omega0, f.omega0_sigma, "rad/s");
    r.add("quality_factor", f.quality, -1, "", "omega0 / (2 sigma)");
    r.add(k ? "mass" : "stiffness", k ? f.mass : f.stiffness, k ? f.mass_sigma : f.stiffness_sigma, k ? "kg" : "N/m",
          "implied by omega0");
    r.add("x_eq", f.oscillator.x_eq, f.x_eq_sigma, "m", "spring rest position");
    r.add("rms_residual", f.rms_residual, -1, "m", "fit residual");
    r.add("ends_at_rest", f.ends_at_rest ? 1 : 0, -1, "", "1: stuck at the end");
  } else {
    r.tables.push_back({"records_columns_normal_force_friction_force_sigma_damping_sigma_rms_residual", rows});
    if (loads.size() >= 3) {
      std::vector<double> fd, fd_sigma;
      for (const auto& f : fits) {
        fd.push_back(f.friction_force);
        fd_sigma.push_back(f.friction_force_sigma);
      }
      const FrictionLine line = fit_load_line(loads, fd, fd_sigma);
      r.add("mu_d", line.mu, line.mu_sigma, "", "slope of F_d = mu_d F_N + mu_d F_adh");
      add_adhesion(r, line, "F_d at zero applied load", foot_area);
      r.add("rms_residual", line.rms_residual, -1, "N", "load line");
      std::vector<double> fn_nN, fd_nN, fit_nN;
      for (std::size_t i = 0; i < fits.size(); ++i) {
        fn_nN.push_back(loads[i] * 1e9);
        fd_nN.push_back(fd[i] * 1e9);
        fit_nN.push_back((line.intercept + line.mu * loads[i]) * 1e9);
      }
      panels.insert(panels.begin(), tools::PlotPanel{"applied normal load F_N (nN)", "dynamic friction F_d (nN)",
                                              "load line (Fig. 2.11)", {{"F_N", fn_nN}, {"records", fd_nN}, {"fit mu_d", fit_nN}}});
    }
  }
  if (json) {
    emit(r, true);
  } else {
    r.print_table(stdout);
    if (files.size() > 1) {
      std::printf("\n%-28s %12s %12s %10s %12s %10s\n", "file", "F_N (N)", "F_d (N)", "+-", "c (N s/m)", "rms (nm)");
      for (std::size_t i = 0; i < files.size(); ++i)
        std::printf("%-28s %12.5g %12.5g %10.3g %12.4g %10.3g\n", files[i].c_str(), rows[i][0], rows[i][1], rows[i][2],
                    rows[i][3], rows[i][5] * 1e9);
    }
  }
  if (!json || plot) {
    const std::string png = plot.value_or(tools::default_plot_path(files.front()));
    if (tools::write_plot(png, "dynamic friction: Coulomb + viscous oscillator fit", panels))
      std::fprintf(stderr, "plot: %s\n", png.c_str());
  }
  return tools::exit_ok;
}

// ---------------------------------------------------------------- synth
constexpr double kMaxSynthSamples = 1e7;  // one synthetic record (ringdown, dynamic)

int synth(const std::vector<std::string>& argv) {
  Args a(argv, "tribex friction-test synth", synth_usage);
  if (a.answered_help()) return tools::exit_ok;
  const std::string cmd = "tribex friction-test synth";
  const std::string kind = a.positional(0, "KIND (ringdown, dynamic or static)");
  const auto out = a.text("-o");
  const double noise = a.quantity("--noise", 10e-9, dim::length);
  const long seed = a.integer("--seed", 1);
  // Every kind's record takes the noise and the seed; then no option may be left and -o is required.
  auto finish = [&](auto& setup) {
    setup.noise = noise;
    setup.seed = static_cast<std::uint64_t>(seed);
    a.finish();
    if (!out) throw BadInput(cmd + ": -o FILE.csv is required");
  };
  if (kind == "ringdown" || kind == "dynamic") {
    OscillatorSetup s;
    s.mass = a.quantity("--mass", s.mass, dim::mass);
    s.stiffness = a.quantity("--stiffness", s.stiffness, dim::stiffness);
    s.damping = a.quantity("--damping", 2 * s.mass * 130.0, inputs::Dimension{1, 0, -1});
    s.friction_force = a.quantity("--friction-force", kind == "dynamic" ? 40e-9 : 0.0, dim::force);
    s.static_force = a.quantity("--static-force", 0.0, dim::force);
    s.x_release = a.quantity("--release", s.x_release, dim::length);
    s.cycles = a.real("--cycles", s.cycles);
    s.samples_per_cycle = a.real("--samples-per-cycle", s.samples_per_cycle);
    finish(s);
    if (s.mass <= 0 || s.stiffness <= 0 || s.damping < 0 || s.cycles <= 0 || s.samples_per_cycle < 4 ||
        s.damping >= 2 * std::sqrt(s.stiffness * s.mass))
      throw BadInput(cmd + ": need mass, stiffness > 0, 0 <= damping < 2 sqrt(k m) (underdamped), cycles > 0, "
                     "samples-per-cycle >= 4");
    // Bounded before allocating (issue 54, item 12; tools/friction_test/README.md): 1e7 samples are
    // 0.8 GB in memory, a 270 MB CSV and about 12 s.
    if (!(s.samples_per_cycle * s.cycles <= kMaxSynthSamples))
      throw BadInput(cmd + ": --cycles " + tools::json_number(s.cycles) + " x --samples-per-cycle " +
                     tools::json_number(s.samples_per_cycle) + " = " + tools::json_number(s.cycles * s.samples_per_cycle) +
                     " samples, more than the limit of 1e7 (0.8 GB in memory); give fewer cycles or samples per cycle");
    synth_oscillator(s, *out).write(*out);
  } else if (kind == "static") {
    StaticSetup s;
    s.stiffness = a.quantity("--stiffness", s.stiffness, dim::stiffness);
    s.mu_s = a.real("--mu-s", s.mu_s);
    s.mu_d = a.real("--mu-d", s.mu_d);
    s.adhesion_force = a.quantity("--adhesion-force", 4.8e-6, dim::force);
    s.clamp.gap = a.quantity("--gap", s.clamp.gap, dim::length);
    s.clamp.electrode_area = a.quantity("--area", s.clamp.electrode_area, dim::area);
    s.x_start = a.quantity("--start-position", s.x_start, dim::length);
    s.volts_start = a.real("--volts-start", s.volts_start);
    s.volts_step = a.real("--volts-step", s.volts_step);
    finish(s);
    if (s.stiffness <= 0 || s.mu_s <= 0 || s.mu_d <= 0 || s.mu_d > s.mu_s || s.volts_step <= 0 || s.volts_start <= 0)
      throw BadInput(cmd + ": need stiffness > 0, 0 < mu_d <= mu_s, volts-start and volts-step > 0");
    synth_static(s, *out).write(*out);
  } else {
    throw BadInput(cmd + ": unknown kind '" + kind + "' (use ringdown, dynamic or static)");
  }
  std::fprintf(stderr, "wrote %s\n", out->c_str());
  return tools::exit_ok;
}

}  // namespace
}  // namespace tribex::friction_test

namespace tribex::cli {

int friction_test_command(const std::vector<std::string>& args) {
  using namespace tribex::friction_test;
  return tools::run_subcommand(args, "tribex friction-test", top_usage,
                               {{"calibrate", calibrate}, {"static", static_friction}, {"dynamic", dynamic_friction},
                                {"synth", synth}});
}

}  // namespace tribex::cli
