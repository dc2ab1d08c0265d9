// SPDX-License-Identifier: MIT
// `tribex surface stats FILE` and `tribex surface mccool FILE1 [FILE2]`: rough-surface statistics of AFM
// height maps and McCool's GW table (report Section 4.3, Table 4.2).
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/afm/height_map.hpp"
#include "mesh/afm/preprocess.hpp"
#include "tools/common/command.hpp"
#include "tools/common/subcommands.hpp"
#include "tools/common/text_file.hpp"
#include "tools/surface/mccool.hpp"
#include "tools/surface/spectral_moments.hpp"
#include "tools/surface/summit_contact.hpp"
#include <sstream>
#include <algorithm>

namespace tribex::cli {
namespace {

using mesh::afm::HeightMap;
using namespace tools::command;

const char* stats_usage =
    "usage: tribex surface stats FILE [options]\n"
    "Spectral moments, bandwidth and summit statistics of an AFM height map (Nayak/McCool).\n"
    "FILE: Nanoscope (.di/.spm/.000), Gwyddion .gsf, Gwyddion ASCII matrix, or x y z text.\n"
    "  --channel N         Nanoscope channel index (default: first height channel)\n"
    "  --window X0,Y0,WX,WY  crop a window in physical units first, e.g. 0,0,100nm,35nm\n"
    "  --level plane|mean|none  subtract the least-squares plane (default), the mean height only (what\n"
    "                      Gwyddion and SurfaceTopography report), or nothing; rms_m is about the mean either way\n"
    "  --resample N        interpolate onto N x N pixels (the report used 1024)\n"
    "  --median            3x3 median filter after resampling\n"
    "  --smooth            3x3 [1 2 1] weighted smoothing after the median filter\n"
    "  --json              JSON instead of the text table\n"
    "  --summits FILE.csv  write the summits found (height_m,radius_m; positive curvature only) for a\n"
    "                      rough-surface contact interaction's 'summit file' (its 'summit map area' is printed)\n"
    "Steps: read, crop, level (--level), resample, median, smooth, then the moments.\n";

const char* mccool_usage =
    "usage: tribex surface mccool FILE1 [FILE2] [options]\n"
    "McCool's GW predictions for two rough surfaces in contact (report Eqs. 4.6-4.9, Table 4.2 layout).\n"
    "Moments of the two maps are added; with one FILE the second surface is taken as smooth.\n"
    "  --channel1 N, --channel2 N   Nanoscope channels (default: first height channel)\n"
    "  --window, --resample N, --median, --smooth   pre-processing, as in `surface stats`, for both maps\n"
    "  --E1 164GPa --nu1 0.23 --E2 164GPa --nu2 0.23   elastic constants (polysilicon defaults)\n"
    "  --separation T      d/sigma_s (default 1), or\n"
    "  --load P            solve for d/sigma_s giving this load on the apparent area, e.g. 10mN\n"
    "  --area-x 10um --area-y 100um   apparent area (default 10 x 100 um^2)\n"
    "  --hardness 11GPa    hardness for the fraction of asperities past it\n"
    "  --json              JSON instead of the text table\n";

struct Prepared {
  HeightMap map;
  std::string steps;
};

// The pre-processing options every subcommand takes (--window, --resample, --median, --smooth).
struct Preprocess {
  std::vector<double> window;  // X0, Y0, WX, WY, m; empty: the whole map
  std::string level = "plane";  // plane | mean | none
  long resample = 0;           // pixels per side; 0: as read
  bool median = false, smooth = false;
};

Preprocess preprocess_options(Args& a) {
  Preprocess o;
  o.window = a.list("--window", inputs::dim::length);
  if (!o.window.empty() && o.window.size() != 4)
    throw BadInput("--window needs 4 lengths X0,Y0,WX,WY (e.g. 0,0,100nm,35nm), got " + std::to_string(o.window.size()));
  o.level = a.text("--level").value_or("plane");
  if (o.level != "plane" && o.level != "mean" && o.level != "none")
    throw BadInput("--level " + o.level + " is not one of plane, mean, none");
  o.resample = a.integer("--resample", 0);
  if (o.resample != 0 && (o.resample < 8 || o.resample > 8192))
    throw BadInput("--resample " + std::to_string(o.resample) + " is out of range; use 8 to 8192 pixels per side");
  o.median = a.flag("--median");
  o.smooth = a.flag("--smooth");
  return o;
}

Prepared prepare(const std::string& file, int channel, const Preprocess& o) {
  Prepared p;
  p.map = mesh::afm::read_height_map(file, channel);
  p.steps = "read";
  if (!o.window.empty()) {
    p.map = mesh::afm::crop(p.map, o.window[0], o.window[1], o.window[2], o.window[3]);
    p.steps += ", crop";
  }
  if (o.level == "plane") p.map = mesh::afm::level_plane(p.map);
  if (o.level == "mean") p.map = mesh::afm::remove_mean(p.map);
  p.steps += ", level " + o.level;
  if (o.resample > 0) {
    p.map = mesh::afm::resample(p.map, static_cast<std::size_t>(o.resample), static_cast<std::size_t>(o.resample));
    p.steps += ", resample " + std::to_string(o.resample);
  }
  if (o.median) { p.map = mesh::afm::median_filter(p.map); p.steps += ", median 3x3"; }
  if (o.smooth) { p.map = mesh::afm::smooth(p.map); p.steps += ", smooth 3x3"; }
  return p;
}

// The elastic constants of the two bodies (--E1 --nu1 --E2 --nu2; polysilicon defaults).
struct ElasticPair {
  double e1 = 0.0, nu1 = 0.0, e2 = 0.0, nu2 = 0.0;  // Pa, -
};

ElasticPair elastic_options(Args& a) {
  ElasticPair e;
  e.e1 = a.quantity("--E1", 164e9, inputs::dim::pressure);
  e.e2 = a.quantity("--E2", 164e9, inputs::dim::pressure);
  e.nu1 = a.real("--nu1", 0.23);
  e.nu2 = a.real("--nu2", 0.23);
  return e;
}

// Checked after a.finish(), so that unknown options are reported first.
void check_elastic(const ElasticPair& e) {
  if (!(e.e1 > 0 && e.e2 > 0)) throw BadInput("--E1 and --E2 must be positive");
  if (!(e.nu1 > -1 && e.nu1 < 0.5 && e.nu2 > -1 && e.nu2 < 0.5)) throw BadInput("--nu1 and --nu2 must lie in (-1, 0.5)");
}

int channel_option(Args& a, const std::string& name) {
  const long c = a.integer(name, -1);
  if (c < -1 || c > 64) throw BadInput(name + " " + std::to_string(c) + " is out of range (0 to 64)");
  return static_cast<int>(c);
}

// `--summits FILE.csv`: the discrete population of the rough-surface contact model
// (contact/models/rough_surface.hpp: `summit file` + `summit map area`), one summit per line.
void write_summits(const std::string& path, const mesh::afm::HeightMap& map, const std::string& source) {
  std::size_t count = 0;  // written whole through write_text_file (a regular file only, never half-written)
  char line[96];
  std::snprintf(line, sizeof line, "map area %.9g m^2\nheight_m,radius_m\n", map.size_x() * map.size_y());
  std::string text = "# summits of " + source + " (8-neighbour maxima, positive curvature), " + line;
  for (const auto& s : surface::find_summits(map))
    if (s.curvature > 0.0) {
      std::snprintf(line, sizeof line, "%.9g,%.9g\n", s.height, 1.0 / s.curvature);
      text += line;
      ++count;
    }
  tools::write_text_file(path, text);
  std::fprintf(stderr, "summits: %zu written to %s; summit map area = %.9g m^2\n", count, path.c_str(),
               map.size_x() * map.size_y());
}

int stats(const std::vector<std::string>& argv) {
  Args a(argv, "tribex surface stats", stats_usage, {"--json", "--median", "--smooth"});
  if (a.answered_help()) return tools::exit_ok;
  const std::string file = a.positional(0, "FILE");
  const int channel = channel_option(a, "--channel");
  const Preprocess pre = preprocess_options(a);
  const bool json = a.flag("--json");
  const auto summits_csv = a.text("--summits");
  a.finish();
  const Prepared p = prepare(file, channel, pre);
  if (summits_csv) write_summits(*summits_csv, p.map, file);
  using surface::Direction;
  const auto mx = surface::profile_moments(p.map, Direction::x), my = surface::profile_moments(p.map, Direction::y);
  const auto mi = surface::isotropic_moments(p.map);
  const auto sx = surface::summit_statistics(mx), sy = surface::summit_statistics(my), si = surface::summit_statistics(mi);
  const auto found = surface::find_summits(p.map);
  const double area = p.map.size_x() * p.map.size_y();
  const double found_density = static_cast<double>(found.size()) / area;
  double mean_k = 0.0, zs = 0.0, zs2 = 0.0;
  for (const auto& s : found) { mean_k += s.curvature; zs += s.height; zs2 += s.height * s.height; }
  const double nf = std::max<double>(1.0, static_cast<double>(found.size()));
  mean_k /= nf; zs /= nf;
  const double found_sigma = std::sqrt(std::max(0.0, zs2 / nf - zs * zs));
  if (json) {
    auto mom = [](const surface::Moments& m, const surface::SummitStatistics& s) {
      char b[512];
      std::snprintf(b, sizeof b,
                    "{\"m0_m2\": %.9g, \"m2\": %.9g, \"m4_per_m2\": %.9g, \"alpha\": %.9g, \"summit_density_per_m2\": %.9g, "
                    "\"summit_radius_m\": %.9g, \"sigma_s_m\": %.9g, \"mean_summit_height_m\": %.9g}",
                    m.m0, m.m2, m.m4, s.alpha, s.density, s.radius, s.sigma_s, s.mean_height);
      return std::string(b);
    };
    std::printf("{\"file\": \"%s\", \"channel\": \"%s\", \"preprocessing\": \"%s\", \"level\": \"%s\", \"nx\": %zu, \"ny\": %zu, "
                "\"dx_m\": %.9g, \"dy_m\": %.9g, \"rms_m\": %.9g,\n \"along_x\": %s,\n \"along_y\": %s,\n \"isotropic\": %s,\n"
                " \"summits_found\": {\"count\": %zu, \"density_per_m2\": %.9g, \"mean_radius_m\": %.9g, \"sigma_m\": %.9g}}\n",
                file.c_str(), p.map.channel.c_str(), p.steps.c_str(), pre.level.c_str(), p.map.nx, p.map.ny, p.map.dx, p.map.dy,
                std::sqrt(mi.m0), mom(mx, sx).c_str(), mom(my, sy).c_str(), mom(mi, si).c_str(), found.size(),
                found_density, mean_k > 0 ? 1.0 / mean_k : 0.0, found_sigma);
    return tools::exit_ok;
  }
  std::printf("file %s, channel %s\n", file.c_str(), p.map.channel.c_str());
  std::printf("map %zu x %zu pixels, %.4g x %.4g um, pixel %.4g x %.4g nm; %s\n", p.map.nx, p.map.ny, p.map.size_x() * 1e6,
              p.map.size_y() * 1e6, p.map.dx * 1e9, p.map.dy * 1e9, p.steps.c_str());
  std::printf("RMS height Rq = sqrt(m0)          %12.5g nm   (levelled: %s)\n\n", std::sqrt(mi.m0) * 1e9, pre.level.c_str());
  std::printf("%-34s %12s %12s %12s\n", "quantity", "along x", "along y", "isotropic");
  auto row = [](const char* name, double a_, double b_, double c_) { std::printf("%-34s %12.5g %12.5g %12.5g\n", name, a_, b_, c_); };
  row("m0 (nm^2)", mx.m0 * 1e18, my.m0 * 1e18, mi.m0 * 1e18);
  row("m2 (-)", mx.m2, my.m2, mi.m2);
  row("m4 (1/nm^2)", mx.m4 * 1e-18, my.m4 * 1e-18, mi.m4 * 1e-18);
  row("bandwidth alpha = m0 m4/m2^2", sx.alpha, sy.alpha, si.alpha);
  row("summit density (1/um^2)", sx.density * 1e-12, sy.density * 1e-12, si.density * 1e-12);
  row("mean summit radius (nm)", sx.radius * 1e9, sy.radius * 1e9, si.radius * 1e9);
  row("summit sigma_s (nm)", sx.sigma_s * 1e9, sy.sigma_s * 1e9, si.sigma_s * 1e9);
  row("mean summit height (nm)", sx.mean_height * 1e9, sy.mean_height * 1e9, si.mean_height * 1e9);
  std::printf("\nsummits found on the map (8-neighbour maxima): %zu, density %.5g /um^2, mean radius %.5g nm, "
              "height std %.5g nm\n",
              found.size(), found_density * 1e-12, mean_k > 0 ? 1e9 / mean_k : 0.0, found_sigma * 1e9);
  return tools::exit_ok;
}

int mccool(const std::vector<std::string>& argv) {
  Args a(argv, "tribex surface mccool", mccool_usage, {"--json", "--median", "--smooth"});
  if (a.answered_help()) return tools::exit_ok;
  const std::string f1 = a.positional(0, "FILE1");
  const auto f2 = a.optional_positional(1);
  const int c1 = channel_option(a, "--channel1"), c2 = channel_option(a, "--channel2");
  const Preprocess pre = preprocess_options(a);
  const ElasticPair elastic = elastic_options(a);
  const auto sep = a.real("--separation");
  const auto load = a.quantity("--load", inputs::dim::force);
  const double ax = a.quantity("--area-x", 10e-6, inputs::dim::length), ay = a.quantity("--area-y", 100e-6, inputs::dim::length);
  const double hardness = a.quantity("--hardness", 11e9, inputs::dim::pressure);
  const bool json = a.flag("--json");
  a.finish();
  if (a.positional_count() > 2) throw BadInput("tribex surface mccool takes one or two FILEs, got " + std::to_string(a.positional_count()));
  if (sep && load) throw BadInput("give either --separation or --load, not both");
  check_elastic(elastic);
  if (!(ax > 0 && ay > 0)) throw BadInput("--area-x and --area-y must be positive");
  if (!(hardness > 0)) throw BadInput("--hardness must be positive");
  const double t = sep.value_or(1.0);
  if (!load && !(t >= -3.0 && t <= 8.0)) throw BadInput("--separation must lie in [-3, 8] (units of sigma_s)");
  const Prepared p1 = prepare(f1, c1, pre);
  surface::Moments m = surface::isotropic_moments(p1.map);
  std::string f2name = "(smooth flat)";
  if (f2) {
    const Prepared p2 = prepare(*f2, c2, pre);
    m = surface::combine(m, surface::isotropic_moments(p2.map));
    f2name = *f2;
  }
  surface::McCoolInput in;
  in.moments = m;
  in.e_star = surface::composite_modulus(elastic.e1, elastic.nu1, elastic.e2, elastic.nu2);
  in.hardness = hardness;
  in.apparent_area = ax * ay;
  surface::McCoolResult r;
  if (load) {
    if (!(*load > 0)) throw BadInput("--load must be positive");
    try {
      r = surface::mccool_at_load(in, *load);
    } catch (const std::domain_error& e) {
      throw BadInput(std::string("--load: ") + e.what());
    }
  } else {
    r = surface::mccool_at_separation(in, t);
  }
  const auto& s = r.summits;
  if (json) {
    std::printf("{\"file1\": \"%s\", \"file2\": \"%s\", \"preprocessing\": \"%s\", \"m0_m2\": %.9g, \"m2\": %.9g, "
                "\"m4_per_m2\": %.9g, \"alpha\": %.9g, \"E_star_Pa\": %.9g, \"apparent_area_m2\": %.9g, \"d_over_sigma_s\": %.9g,\n"
                " \"summit_density_per_m2\": %.9g, \"summit_radius_m\": %.9g, \"sigma_s_m\": %.9g, \"contacts\": %.9g, "
                "\"area_ratio\": %.9g, \"true_area_m2\": %.9g, \"load_N\": %.9g, \"mean_pressure_Pa\": %.9g, "
                "\"hardness_Pa\": %.9g, \"fraction_past_hardness\": %.9g}\n",
                f1.c_str(), f2name.c_str(), p1.steps.c_str(), m.m0, m.m2, m.m4, s.alpha, in.e_star, in.apparent_area, r.t,
                s.density, s.radius, s.sigma_s, r.contacts, r.area_ratio, r.true_area, r.load, r.mean_pressure, hardness,
                r.fraction_past_hardness);
    return tools::exit_ok;
  }
  std::printf("surfaces: %s + %s (%s)\n", f1.c_str(), f2name.c_str(), p1.steps.c_str());
  std::printf("combined moments m0 = %.5g nm^2, m2 = %.5g, m4 = %.5g 1/nm^2, alpha = %.5g; E* = %.5g GPa\n", m.m0 * 1e18,
              m.m2, m.m4 * 1e-18, s.alpha, in.e_star * 1e-9);
  std::printf("separation d/sigma_s = %.5g%s; apparent area %.4g x %.4g um^2\n\n", r.t, load ? " (solved for the load)" : "",
              ax * 1e6, ay * 1e6);
  std::printf("%-58s %12s\n", "parameter (units)", "value");
  std::printf("%-58s %12.4g\n", "summit density (/um^2)", s.density * 1e-12);
  std::printf("%-58s %12.4g\n", "average summit radius (nm)", s.radius * 1e9);
  std::printf("%-58s %12.4g\n", "sigma_s, std of summit height distribution (nm)", s.sigma_s * 1e9);
  std::printf("number of contact points for a %.4g x %.4g um^2 area%*s %12.4g\n", ax * 1e6, ay * 1e6, 10, "", r.contacts);
  std::printf("%-58s %12.4g\n", "ratio of true to apparent contact area", r.area_ratio);
  std::printf("%-58s %12.4g\n", "true contact area (um^2)", r.true_area * 1e12);
  std::printf("%-58s %12.4g\n", "load (mN)", r.load * 1e3);
  std::printf("%-58s %12.4g\n", "average contact pressure (MPa)", r.mean_pressure * 1e-6);
  std::printf("%-58s %12.4g\n", "fraction of contacting asperities past the hardness", r.fraction_past_hardness);
  return tools::exit_ok;
}

const char* contact_usage =
    "usage: tribex surface contact FILE [options]\n"
    "Discrete GW over the summits found on the map (8-neighbour maxima, own radius each; report Eq. 4.2),\n"
    "Hertz and DMT (Eq. 4.11), for a rigid flat lowered from the highest summit: CSV with columns\n"
    "h_m, contacts, area_fraction, pressure_hertz_Pa, pressure_dmt_Pa (pressures over the map area).\n"
    "  --channel N, --window, --resample N, --median, --smooth   as in `surface stats`\n"
    "  --E1 164GPa --nu1 0.23 --E2 164GPa --nu2 0.23   elastic constants of the two bodies\n"
    "  --work-of-adhesion 0.1J/m^2   W of the DMT term\n"
    "  --points 200        flat positions from the highest summit down to the mean plane (geometric approach)\n"
    "  --csv FILE          output (default: stdout)\n";

int contact(const std::vector<std::string>& argv) {
  Args a(argv, "tribex surface contact", contact_usage, {"--median", "--smooth"});
  if (a.answered_help()) return tools::exit_ok;
  const std::string file = a.positional(0, "FILE");
  const int channel = channel_option(a, "--channel");
  const Preprocess pre = preprocess_options(a);
  const ElasticPair elastic = elastic_options(a);
  const double w = a.quantity("--work-of-adhesion", 0.1, inputs::dim::energy_per_area);
  const long points = a.integer("--points", 200);
  const std::string csv = a.text("--csv", "");
  a.finish();
  check_elastic(elastic);
  if (!(w >= 0)) throw BadInput("--work-of-adhesion must be >= 0");
  if (points < 2 || points > 100000) throw BadInput("--points must lie in 2 to 100000");
  const Prepared p = prepare(file, channel, pre);
  const auto summits = surface::find_summits(p.map);
  if (summits.empty()) throw BadInput(file + ": no summits found on the map; nothing to put in contact");
  double top = -1e300;
  for (const auto& s : summits) top = std::max(top, s.height);
  const double e_star = surface::composite_modulus(elastic.e1, elastic.nu1, elastic.e2, elastic.nu2);
  const double area = p.map.size_x() * p.map.size_y();
  std::ostringstream o;
  o << "h_m,contacts,area_fraction,pressure_hertz_Pa,pressure_dmt_Pa\n";
  char b[200];
  for (long i = 0; i < points; ++i) {
    // Approach delta = top - h spaced geometrically from 1e-6 top to top, so the first contacts (where
    // adhesion matters) are resolved as well as the approach down to the mean plane.
    const double delta = i == 0 ? 0.0 : top * std::pow(1e-6, 1.0 - static_cast<double>(i - 1) / static_cast<double>(points - 2));
    const double h = top - delta;
    const auto c = surface::summit_contact(summits, e_star, w, h);
    std::snprintf(b, sizeof b, "%.9g,%zu,%.9g,%.9g,%.9g\n", h, c.contacts, c.area / area, c.load_hertz / area, c.load_dmt / area);
    o << b;
  }
  tools::write_text_output(csv, o.str());
  return tools::exit_ok;
}

}  // namespace

int surface_command(const std::vector<std::string>& args) {
  const char* usage =
      "usage: tribex surface stats FILE [options]      spectral moments and summit statistics\n"
      "       tribex surface mccool FILE1 [FILE2] ...  McCool GW table for two surfaces in contact\n"
      "       tribex surface contact FILE ...          discrete Hertz/DMT GW over the map's own summits (CSV)\n"
      "(tribex surface SUB --help for details)\n";
  return tools::run_subcommand(args, "tribex surface", usage, {{"stats", stats}, {"mccool", mccool}, {"contact", contact}});
}

}  // namespace tribex::cli
