// SPDX-License-Identifier: MIT
// `tribex adhesion-curve`: the Lennard-Jones sphere-flat reference (docs/theory.md 6.7): the
// load-approach curve through both branches, pull-off, jump-in and jump-out, as CSV, JSON and a PNG.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "inputs/units.hpp"
#include "tools/adhesion/report.hpp"
#include "tools/cli/commands.hpp"
#include "tools/common/command.hpp"
#include "tools/common/text_file.hpp"

namespace tribex::adhesion {
namespace {

using namespace tools::command;

const char* usage =
    "usage: tribex adhesion-curve [--radius 27nm | --tabor MU] [--work 0.05J/m^2] [--z0 0.3nm] [--cutoff H_C]\n"
    "         [--e-star E* | --youngs 161GPa --poisson 0.23] [--max-load P | --max-load-bar 3] [--contact-gap G_J]\n"
    "         [--resolution 8] [--penalty 1000] [-o DIR] [--no-plot] [--json]\n"
    "An elastic sphere (paraboloid, radius R) on a flat, both with the composite modulus E*\n"
    "(default: Si on Si, E*= E/(2(1-nu^2))), interacting by the law of `model = adhesion`: the Lennard-Jones 3-9\n"
    "traction (work W, equilibrium separation z0, cut-off separation h_c, default 20 z0, shifted to be\n"
    "continuous) outside contact and hard contact (a stiff penalty, k = PENALTY E*/z0) inside, solved\n"
    "self-consistently on rings (docs/theory.md 6.7, tools/adhesion/README.md). The curve is traced from out\n"
    "of range through contact to the largest load --max-load (N) or --max-load-bar (in pi W_c R, default 3;\n"
    "--max-load is required when W = 0).\n"
    "--tabor MU sets R = MU^3 E*^2 z0^3/W^2 (mu_T = (R W^2/(E*^2 z0^3))^(1/3)). --contact-gap: the contact radius is where\n"
    "g <= g_j (the FE's in-contact rule, default 0.05 z0; 0 when W = 0). --resolution: rings per\n"
    "shortest gap length at the contact edge (Eq. 6.7.5). Writes DIR/adhesion.csv (the curve, SI and\n"
    "normalised), DIR/limits.csv (DMT, JKR, Maugis-Dugdale), DIR/summary.json (pull-off under load control,\n"
    "jump-out and jump-in under displacement control) and DIR/adhesion.png (default DIR = adhesion_output).\n";

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

void draw(const std::string& dir) {
  const std::string cmd = "/usr/bin/python3 " + shell_quote(TRIBEX_ADHESION_PLOT_SCRIPT) + " " + shell_quote(dir);
  if (std::system(cmd.c_str()) != 0)
    std::fprintf(stderr, "warning: %s/adhesion.png was not drawn (/usr/bin/python3 with matplotlib failed); the CSV is complete\n",
                 dir.c_str());
}

double composite_modulus(Args& a) {
  const auto e_star = a.quantity("--e-star", dim::pressure);
  const auto e = a.quantity("--youngs", dim::pressure);
  const auto nu = a.real("--poisson");
  if (e_star && (e || nu)) throw BadInput("tribex adhesion-curve: give --e-star or --youngs/--poisson, not both");
  if (e_star) {
    if (!(*e_star > 0)) throw BadInput("tribex adhesion-curve: --e-star must be > 0 (e.g. --e-star 85GPa)");
    return *e_star;
  }
  const double ev = e.value_or(161e9), nv = nu.value_or(0.23);
  if (!(ev > 0) || !(nv > -1 && nv < 0.5))
    throw BadInput("tribex adhesion-curve: --youngs must be > 0 and -1 < --poisson < 0.5 (defaults 161GPa, 0.23)");
  return ev / (2 * (1 - nv * nv));
}

// Reads and checks every argument before anything is computed or written.
Problem parse_problem(Args& a, CurveSettings& set) {
  Problem pb;
  pb.e_star = composite_modulus(a);
  auto& law = pb.law.law;
  law.work = a.quantity("--work", 0.05, dim::energy_per_area);
  law.z0 = a.quantity("--z0", 0.3e-9, dim::length);
  if (!(law.work >= 0)) throw BadInput("tribex adhesion-curve: --work must be >= 0 (e.g. --work 0.05J/m^2)");
  if (!(law.z0 > 0)) throw BadInput("tribex adhesion-curve: --z0 must be > 0 (e.g. --z0 0.3nm)");
  law.cutoff = a.quantity("--cutoff", 20 * law.z0, dim::length);
  if (!(law.cutoff > 1.5 * law.z0) || law.cutoff > 1000 * law.z0)
    throw BadInput("tribex adhesion-curve: --cutoff must lie between 1.5 z0 and 1000 z0 (a separation like h; default 20 z0)");
  const auto radius = a.quantity("--radius", dim::length);
  const auto tabor = a.real("--tabor");
  if (radius && tabor) throw BadInput("tribex adhesion-curve: give --radius or --tabor, not both");
  if (tabor && !(*tabor >= 1e-3 && *tabor <= 30 && law.work > 0))
    throw BadInput("tribex adhesion-curve: --tabor takes 0.001..30 and needs --work > 0");
  pb.radius = tabor ? radius_at_tabor(*tabor, pb.e_star, law.work, law.z0) : radius.value_or(27e-9);
  if (!(pb.radius > 0)) throw BadInput("tribex adhesion-curve: --radius must be > 0 (e.g. --radius 27nm)");
  pb.contact_gap = a.quantity("--contact-gap", law.work > 0 ? 0.05 * law.z0 : 0.0, dim::length);
  if (!(pb.contact_gap >= 0 && pb.contact_gap < 0.2 * law.z0))
    throw BadInput("tribex adhesion-curve: --contact-gap takes 0 <= g_j < 0.2 z0 (the FE's junction gap tolerance; default 0.05 z0)");
  const double kappa = a.real("--penalty", 1000);
  if (!(kappa >= 10 && kappa <= 1e6)) throw BadInput("tribex adhesion-curve: --penalty takes 10..1e6 (k = PENALTY E*/z0; default 1000)");
  pb.law.penalty = kappa * pb.e_star / law.z0;
  set.points_per_length = a.real("--resolution", set.points_per_length);
  if (!(set.points_per_length >= 2 && set.points_per_length <= 100))
    throw BadInput("tribex adhesion-curve: --resolution takes 2..100 rings per gap length (default 8)");
  const auto max_load = a.quantity("--max-load", dim::force);
  const auto max_load_bar = a.real("--max-load-bar");
  if (max_load && max_load_bar) throw BadInput("tribex adhesion-curve: give --max-load or --max-load-bar, not both");
  if (!max_load && law.work == 0) throw BadInput("tribex adhesion-curve: --work 0 needs --max-load (e.g. --max-load 50nN)");
  set.max_load = max_load.value_or(max_load_bar.value_or(3) * M_PI * pb.law.captured_work() * pb.radius);
  if (!(set.max_load > 0)) throw BadInput("tribex adhesion-curve: --max-load must be > 0 (e.g. --max-load 50nN)");
  return pb;
}

}  // namespace

int run(const std::vector<std::string>& argv) {
  Args a(argv, "tribex adhesion-curve", usage, {"--no-plot", "--json"});
  if (a.answered_help()) return tools::exit_ok;
  CurveSettings set;
  const Problem pb = parse_problem(a, set);
  const std::string dir = a.text("-o", "adhesion_output");
  const bool plot = !a.flag("--no-plot"), json = a.flag("--json");
  a.finish();
  for (const char* f : {"/adhesion.csv", "/limits.csv", "/summary.json"}) tools::require_output_file(dir + f);

  const auto t0 = std::chrono::steady_clock::now();
  const Curve c = trace_curve(pb, set);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Scales s = scales_of(pb);
  std::ostringstream about;
  about << "R = " << pb.radius * 1e9 << " nm, E* = " << pb.e_star * 1e-9 << " GPa, W = " << pb.law.law.work
        << " J/m^2, z0 = " << pb.law.law.z0 * 1e9 << " nm, h_c = " << pb.law.law.cutoff * 1e9 << " nm, mu_T = " << s.tabor;
  std::filesystem::create_directories(dir);
  tools::write_text_file(dir + "/adhesion.csv", curve_csv(c, pb, about.str()));
  double max_a_bar = 2.5;
  if (s.radius > 0) max_a_bar = std::max(0.5, c.points.back().contact_radius / s.radius * 1.05);
  tools::write_text_file(dir + "/limits.csv", limits_csv(s, max_a_bar));
  const std::string js = summary_json(c, pb, seconds);
  tools::write_text_file(dir + "/summary.json", js);
  if (json) {
    std::fputs(js.c_str(), stdout);
  } else {
    std::printf("%s\n%zu points, up to %d rings (%.2f s)\n", about.str().c_str(), c.points.size(), c.max_rings, seconds);
    if (s.load > 0) {
      std::printf("pull-off (load control)   P/(pi W_c R) = %.5f (%.4g nN) at delta = %.4g z0, a = %.4g nm\n",
                  c.pull_off.load / s.load, c.pull_off.load * 1e9, c.pull_off.approach / pb.law.law.z0, c.pull_off.contact_radius * 1e9);
      if (c.jump_out.found)
        std::printf("jump-out (displ. control) P/(pi W_c R) = %.5f  at delta = %.4g z0, a = %.4g nm\n", c.jump_out.load / s.load,
                    c.jump_out.approach / pb.law.law.z0, c.jump_out.contact_radius * 1e9);
      else
        std::printf("jump-out: none (the withdrawal is continuous under displacement control)\n");
      if (c.jump_in.found)
        std::printf("jump-in  (displ. control) P/(pi W_c R) = %.5f  at delta = %.4g z0\n", c.jump_in.load / s.load,
                    c.jump_in.approach / pb.law.law.z0);
      else
        std::printf("jump-in: none (the approach is continuous under displacement control)\n");
    }
    std::printf("wrote %s/adhesion.csv, limits.csv, summary.json\n", dir.c_str());
  }
  if (plot) draw(dir);
  return tools::exit_ok;
}

}  // namespace tribex::adhesion

namespace tribex::cli {
int adhesion_curve_command(const std::vector<std::string>& args) { return adhesion::run(args); }
}  // namespace tribex::cli
