// SPDX-License-Identifier: MIT
// `tribex pstd`: the pre-sliding tangential deflection model of the seed report, Section 2.1.9.
// Builds the substrate and counterface profiles, runs the quasi-static stepping (tools/pstd/stepping.hpp),
// detects PSTD events (events.hpp), and writes CSV, JSON and PNG plots into the output folder.
#include <cctype>
#include <chrono>
#include <map>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"
#include "tools/pstd/counterface.hpp"
#include "tools/pstd/deck.hpp"
#include "tools/pstd/events.hpp"
#include "tools/pstd/output.hpp"
#include "tools/pstd/profile_sources.hpp"
#include "tools/pstd/stepping.hpp"

namespace tribex::cli {

namespace {

const char* usage =
    "usage: tribex pstd [DECK.i] [options]\n"
    "\n"
    "Quasi-static 2-D model of pre-sliding tangential deflection (seed report, Section 2.1.9): a rigid\n"
    "counterface of linked line scans is pressed onto a substrate line to a normal force; it advances 1 grid\n"
    "step whenever the restoring force exceeds the shear capacity tau*A, otherwise it is lifted (normal force\n"
    "reduced) until it does. Lengths and forces take units (10nm, 2um, 50uN); plain numbers are SI.\n"
    "A deck (first argument) holds 'begin pstd' ... 'end pstd' with 'key = value' lines (keys below);\n"
    "options after it override its values.\n"
    "\n"
    "profiles (default: seeded synthetic Gaussian-correlated lines):\n"
    "  --afm FILE              height map (Gwyddion ASCII matrix .txt): substrate = a row, segments = columns\n"
    "  --line N                row of --afm used as substrate (default: chosen from --seed)\n"
    "  --substrate-file FILE   substrate profile: 'x[nm],z[nm]' CSV, or one z per line with --dx\n"
    "  --counterface-file FILE counterface profile (same format), cut into --segments pieces\n"
    "  --dx LEN                sample spacing of one-column profile files\n"
    "  --rms LEN               synthetic RMS roughness (2.7nm)\n"
    "  --corr LEN              synthetic correlation length xi, ACF exp(-x^2/xi^2) (40nm)\n"
    "  --source-dx LEN         synthetic source sample spacing, like the AFM pixel (10nm)\n"
    "  --substrate-length LEN  synthetic substrate length (10um)\n"
    "  --segments K            counterface line scans linked end to end (3)\n"
    "  --segment-length LEN    length of each counterface scan (2um)\n"
    "  --seed S                seed of every random choice (1)\n"
    "  --sampling LEN          model grid: profiles oversampled by linear interpolation (1nm)\n"
    "mechanics:\n"
    "  --law 2d|3d             2d: line contact eq. (2.5) (default); 3d: Hertz eq. (2.6)\n"
    "  --E P, --nu X           Young's modulus and Poisson ratio of both bodies (161GPa, 0.23)\n"
    "  --depth LEN             out-of-plane length of the 2-D model (50um)\n"
    "  --tau P                 junction shear strength tau* (195MPa)\n"
    "  --normal-force F        initial normal force per counterface copy (2.2mN)\n"
    "  --restoring c0,c1,...   restoring force polynomial, uN with x in um\n"
    "                          (0.5796,4.3572,0.1080,0.0435,-0.0001: eq. 2.8)\n"
    "  --travel LEN            sliding distance (default: the substrate length; the substrate is periodic)\n"
"  --start-displacement LEN  device displacement x0 at the start; each advance reduces x by one grid\n"
    "                          step toward neutral (default: --travel, so x runs from travel to 0)\n"
    "  --copies N              copies of the counterface moving in unison (1)\n"
    "  --study                 also run 1..N copies (apparent-area study, report Fig. 2.24)\n"
    "PSTD detection (see tools/pstd/README.md):\n"
    "  --pstd-length-factor X  event extent >= X a, a = mean half-width in the event (10)\n"
    "  --pstd-gap-factor X     lifts at most X a apart belong to one event (1)\n"
    "output:\n"
    "  -o DIR                  output folder (pstd_output): trajectory.csv events.csv initial_contacts.csv\n"
    "                          summary.json normal_force.png contacts_area.png [area_study.csv/.png]\n"
    "  --no-plots              skip the PNG plots (they need /usr/bin/python3 with matplotlib)\n"
    "  --quiet                 print nothing on success\n";

/// The option named in a BadInput message ("tribex pstd --copies: ..." or "... --copies must ..."), if any.
std::string option_in(const std::string& message, const std::map<std::string, std::string>& where) {
  std::string best;
  for (const auto& [option, at] : where) {
    for (auto pos = message.find(option); pos != std::string::npos; pos = message.find(option, pos + 1)) {
      const std::size_t end = pos + option.size();
      const bool word_end = end == message.size() || !(std::isalnum(static_cast<unsigned char>(message[end])) ||
                                                        message[end] == '-');
      if (word_end && option.size() > best.size()) best = option;
    }
  }
  return best;
}

using pstd::Profile;

struct Profiles {
  Profile substrate;
  std::vector<Profile> segments;
};

Profiles make_profiles(tools::Args& a, double dx, std::uint64_t seed) {
  namespace dim = inputs::dim;
  const long segments = a.integer("--segments", 3);
  const double segment_length = a.quantity("--segment-length", 2e-6, dim::length);
  const auto afm = a.text("--afm");
  const long line = a.integer("--line", -1);
  const auto substrate_file = a.text("--substrate-file");
  const auto counterface_file = a.text("--counterface-file");
  const auto file_dx = a.quantity("--dx", dim::length);
  const double rms = a.quantity("--rms", 2.7e-9, dim::length);
  const double corr = a.quantity("--corr", 40e-9, dim::length);
  const double source_dx = a.quantity("--source-dx", 10e-9, dim::length);
  const double substrate_length = a.quantity("--substrate-length", 10e-6, dim::length);
  if (segments < 1 || segments > 1000) throw tools::BadInput("tribex pstd: --segments must be 1..1000");
  if (!(segment_length > 0)) throw tools::BadInput("tribex pstd: --segment-length must be positive");
  if (afm && (substrate_file || counterface_file))
    throw tools::BadInput("tribex pstd: give either --afm or --substrate-file/--counterface-file, not both");
  if (line != -1 && !afm) throw tools::BadInput("tribex pstd: --line selects a row of --afm; add --afm FILE");
  if (!(rms >= 0) || !(corr > 0) || !(source_dx > 0) || !(substrate_length > 0))
    throw tools::BadInput("tribex pstd: --rms must be >= 0 and --corr, --source-dx, --substrate-length > 0");
  if (source_dx < dx) throw tools::BadInput("tribex pstd: --source-dx must not be finer than --sampling");

  Profiles p;
  const auto k_segments = static_cast<std::size_t>(segments);
  if (afm) {
    const pstd::HeightMap map = pstd::read_height_map(*afm);
    if (line >= static_cast<long>(map.ny))
      throw tools::BadInput("tribex pstd: --line " + std::to_string(line) + " is beyond the " +
                            std::to_string(map.ny) + " rows of " + *afm + " (use 0.." + std::to_string(map.ny - 1) + ")");
    const std::size_t row = line >= 0 ? static_cast<std::size_t>(line) : pstd::seeded_index(seed, 0, map.ny);
    pstd::RawProfile sub = map.row(row);
    pstd::level(sub.z);  // AFM line levelling
    p.substrate = pstd::periodic_fine(sub, dx);
    const double column_length = map.dy * static_cast<double>(map.ny - 1);
    if (segment_length > column_length)
      throw tools::BadInput("tribex pstd: --segment-length is longer than the map's columns (" +
                            std::to_string(column_length * 1e6) + " um)");
    for (std::size_t k = 0; k < k_segments; ++k) {
      const std::size_t col = pstd::seeded_index(seed, 100 + k, map.nx);
      const auto slots = static_cast<std::size_t>((column_length - segment_length) / map.dy) + 1;
      const double start = map.dy * static_cast<double>(pstd::seeded_index(seed, 200 + k, slots));
      p.segments.push_back(pstd::window_fine(map.column(col), start, segment_length, dx, true));
      p.segments.back().origin += " from " + std::to_string(start * 1e9) + " nm";
    }
    return p;
  }
  if (substrate_file) {
    p.substrate = pstd::periodic_fine(pstd::read_profile_file(*substrate_file, file_dx), dx);
  } else {
    const auto n = static_cast<std::size_t>(std::llround(substrate_length / source_dx));
    if (n < 8) throw tools::BadInput("tribex pstd: --substrate-length must be at least 8 --source-dx");
    pstd::RawProfile raw;
    raw.z = pstd::synthetic_line(n, source_dx, rms, corr, seed, 0);
    for (std::size_t i = 0; i < n; ++i) raw.x.push_back(source_dx * static_cast<double>(i));
    raw.origin = "synthetic seed " + std::to_string(seed) + " line 0";
    p.substrate = pstd::periodic_fine(raw, dx);
  }
  if (counterface_file) {
    const pstd::RawProfile raw = pstd::read_profile_file(*counterface_file, file_dx);
    for (std::size_t k = 0; k < k_segments; ++k)
      p.segments.push_back(
          pstd::window_fine(raw, raw.x.front() + segment_length * static_cast<double>(k), segment_length, dx, false));
  } else {
    const auto n = static_cast<std::size_t>(std::ceil(segment_length / source_dx)) + 1;
    for (std::size_t k = 0; k < k_segments; ++k) {
      pstd::RawProfile raw;
      raw.z = pstd::synthetic_line(2 * n, source_dx, rms, corr, seed, k + 1);
      raw.z.resize(n);
      for (std::size_t i = 0; i < n; ++i) raw.x.push_back(source_dx * static_cast<double>(i));
      raw.origin = "synthetic seed " + std::to_string(seed) + " line " + std::to_string(k + 1);
      p.segments.push_back(pstd::window_fine(raw, 0.0, segment_length, dx, false));
    }
  }
  return p;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

int pstd_run(const std::vector<std::string>& args);

}  // namespace

int pstd_command(const std::vector<std::string>& cli_args) {
  // A deck as first argument expands to options; options after it override the deck's.
  pstd::DeckArgs deck;
  std::vector<std::string> args = cli_args;
  if (!args.empty() && !args[0].empty() && args[0][0] != '-') {
    deck = pstd::read_deck(args[0]);
    args.erase(args.begin());
    for (const auto& option : args) deck.where.erase(option);  // overridden: errors are the command line's
    args.insert(args.begin(), deck.args.begin(), deck.args.end());
  }
  try {
    return pstd_run(args);
  } catch (const tools::BadInput& e) {
    const std::string option = option_in(e.what(), deck.where);
    if (option.empty()) throw;
    throw tools::BadInput(deck.where.at(option) + ": " + e.what());
  }
}

namespace {

int pstd_run(const std::vector<std::string>& args) {
  namespace dim = inputs::dim;
  tools::Args a(args, "tribex pstd", usage, {"--study", "--no-plots", "--quiet"});
  if (a.help_requested()) {
    std::fputs(usage, stdout);
    std::fputs("\ndeck keys (deck key, option):\n", stdout);
    std::fputs(pstd::deck_keys_help().c_str(), stdout);
    return tools::exit_ok;
  }
  // 1. Everything is read and checked before anything is computed or written.
  const double dx = a.quantity("--sampling", 1e-9, dim::length);
  const long seed_arg = a.integer("--seed", 1);
  const std::string law = a.text("--law", "2d");
  const double e = a.quantity("--E", 161e9, dim::pressure);
  const double nu = a.real("--nu", 0.23);
  const double depth = a.quantity("--depth", 50e-6, dim::length);
  const double tau = a.quantity("--tau", 195e6, dim::pressure);
  const double normal_force = a.quantity("--normal-force", 2.2e-3, dim::force);
  std::vector<double> restoring = a.list("--restoring", dim::none);
  const auto travel_arg = a.quantity("--travel", dim::length);
  const auto start_displacement = a.quantity("--start-displacement", dim::length);
  const long copies = a.integer("--copies", 1);
  const bool study = a.flag("--study");
  pstd::DetectionRule rule;
  rule.length_factor = a.real("--pstd-length-factor", rule.length_factor);
  rule.gap_factor = a.real("--pstd-gap-factor", rule.gap_factor);
  const std::string out_dir = a.text("-o", "pstd_output");
  const bool plots = !a.flag("--no-plots");
  const bool quiet = a.flag("--quiet");
  if (!(dx > 0)) throw tools::BadInput("tribex pstd: --sampling must be positive (e.g. 1nm)");
  if (seed_arg < 0) throw tools::BadInput("tribex pstd: --seed must be >= 0");
  if (law != "2d" && law != "3d") throw tools::BadInput("tribex pstd: --law must be 2d or 3d, got '" + law + "'");
  if (!(e > 0) || !(nu > -1 && nu < 0.5)) throw tools::BadInput("tribex pstd: need --E > 0 and -1 < --nu < 0.5");
  if (!(depth > 0) || !(tau > 0) || !(normal_force > 0))
    throw tools::BadInput("tribex pstd: --depth, --tau and --normal-force must be positive");
  if (copies < 1 || copies > 1000) throw tools::BadInput("tribex pstd: --copies must be 1..1000");
  if (!(rule.length_factor > 0) || !(rule.gap_factor >= 0))
    throw tools::BadInput("tribex pstd: --pstd-length-factor must be > 0 and --pstd-gap-factor >= 0");
  if (restoring.empty()) restoring = {0.5796, 4.3572, 0.1080, 0.0435, -0.0001};  // eq. (2.8)
  const auto seed = static_cast<std::uint64_t>(seed_arg);
  const Profiles profiles = make_profiles(a, dx, seed);
  a.finish();

  pstd::Mechanics mech;
  mech.law = law == "2d" ? pstd::ContactLaw::line_2d : pstd::ContactLaw::hertz_3d;
  mech.modulus = pstd::effective_modulus(e, nu, e, nu);
  mech.depth = depth;
  mech.shear_strength = tau;
  const double substrate_length = profiles.substrate.length();
  const double travel = travel_arg ? *travel_arg : substrate_length;
  if (!(travel >= 0) || travel > substrate_length * (1 + 1e-12))
    throw tools::BadInput("tribex pstd: --travel must be between 0 and the substrate length (" +
                          number(substrate_length * 1e6) + " um)");
  pstd::Drive drive;
  drive.restoring_uN_per_um_pow = restoring;
  drive.steps = static_cast<std::size_t>(std::floor(travel / dx + 1e-9));
  drive.start_displacement = start_displacement ? *start_displacement : travel;
  if (drive.start_displacement < travel * (1 - 1e-12))
    throw tools::BadInput("tribex pstd: --start-displacement must be at least --travel: the device moves back "
                          "toward its neutral position x = 0 and cannot pass it");
  double counterface_length = 0.0;
  for (const auto& s : profiles.segments) counterface_length += s.length();

  // 2. Runs: the main one with `copies` copies, and with --study every count 1..copies.
  std::vector<pstd::StudyRow> rows;
  const long first = study ? 1 : copies;
  for (long n = first; n <= copies; ++n) {
    const auto t0 = std::chrono::steady_clock::now();
    pstd::StudyRow row;
    row.copies = static_cast<std::size_t>(n);
    row.apparent_length = counterface_length * static_cast<double>(n);
    row.normal_force = normal_force * static_cast<double>(n);  // constant apparent pressure across copies
    const pstd::Model model = pstd::build_model(profiles.substrate, profiles.segments, row.copies, mech);
    drive.normal_force = row.normal_force;
    row.run = pstd::simulate(model, drive);
    row.events = pstd::detect_pstd(row.run, rule);
    row.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rows.push_back(std::move(row));
  }
  const pstd::StudyRow& main = rows.back();
  const pstd::Model main_model = pstd::build_model(profiles.substrate, profiles.segments, main.copies, mech);
  const auto contacts = pstd::initial_contacts(main_model, main.normal_force);

  // 3. Outputs.
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) throw tools::BadInput(out_dir + ": cannot create the output folder (" + ec.message() + "); choose another -o");
  const std::string dir = out_dir + "/";
  pstd::write_trajectory_csv(dir + "trajectory.csv", main.run, main.events);
  pstd::write_events_csv(dir + "events.csv", main.events);
  pstd::write_contacts_csv(dir + "initial_contacts.csv", contacts);
  if (study) {
    pstd::write_study_csv(dir + "area_study.csv", rows);
    pstd::write_study_trajectories_csv(dir + "study_trajectories.csv", rows);
  }
  const double a_ref = pstd::reference_half_width(main.run);
  {
    std::FILE* f = std::fopen((dir + "summary.json").c_str(), "w");
    if (!f) throw tools::BadInput(dir + "summary.json: cannot write; check the output folder");
    std::string segs;
    for (const auto& s : profiles.segments) segs += (segs.empty() ? "" : ", ") + pstd::json_string(s.origin);
    std::fprintf(f,
                 "{\n  \"model\": \"pstd\",\n  \"law\": \"%s\",\n  \"seed\": %lu,\n  \"substrate\": %s,\n"
                 "  \"counterface_segments\": [%s],\n  \"substrate_length_um\": %s,\n  \"counterface_length_um\": %s,\n"
                 "  \"sampling_nm\": %s,\n  \"curvature_span_nm\": %s,\n  \"effective_modulus_GPa\": %s,\n"
                 "  \"depth_um\": %s,\n  \"tau_MPa\": %s,\n  \"copies\": %zu,\n  \"normal_force_uN\": %s,\n"
                 "  \"travel_um\": %s,\n  \"initial_contacts\": %d,\n  \"initial_true_area_um2\": %s,\n"
                 "  \"final_normal_force_uN\": %s,\n  \"reference_half_width_nm\": %s,\n  \"pstd_events\": %zu,\n"
                 "  \"contacts_beyond_2d_law_range\": %zu,\n  \"wall_time_s\": %s\n}\n",
                 law.c_str(), static_cast<unsigned long>(seed), pstd::json_string(profiles.substrate.origin).c_str(),
                 segs.c_str(), number(substrate_length * 1e6).c_str(), number(counterface_length * 1e6).c_str(),
                 number(dx * 1e9).c_str(), number(main_model.curvature_span * dx * 1e9).c_str(),
                 number(mech.modulus * 1e-9).c_str(), number(depth * 1e6).c_str(), number(tau * 1e-6).c_str(),
                 main.copies, number(main.normal_force * 1e6).c_str(), number(travel * 1e6).c_str(),
                 main.run.initial_contacts, number(main.run.initial_area * 1e12).c_str(),
                 number(main.run.steps.back().normal_force * 1e6).c_str(), number(a_ref * 1e9).c_str(),
                 main.events.size(), main.run.clamped_contacts, number(main.wall_seconds).c_str());
    std::fclose(f);
  }
  if (plots) {
    const std::string cmd = std::string("/usr/bin/python3 '") + TRIBEX_PSTD_PLOT_SCRIPT + "' '" + out_dir + "'";
    if (std::system(cmd.c_str()) != 0) {
      std::fprintf(stderr, "tribex pstd: plotting failed (%s); the CSV files are written; rerun with --no-plots "
                           "to skip plots\n", cmd.c_str());
      return tools::exit_internal_error;
    }
  }
  if (!quiet) {
    std::printf("pstd: %zu copy(ies), W = %.4g uN, %d initial contacts, %zu PSTD event(s), final W = %.4g uN, "
                "%.3f s -> %s/\n",
                main.copies, main.normal_force * 1e6, main.run.initial_contacts, main.events.size(),
                main.run.steps.back().normal_force * 1e6, main.wall_seconds, out_dir.c_str());
    if (study)
      for (const auto& r : rows)
        std::printf("  study: %3zu copies  %4d initial contacts  %zu PSTD event(s)  %.3f s\n", r.copies,
                    r.run.initial_contacts, r.events.size(), r.wall_seconds);
  }
  return tools::exit_ok;
}

}  // namespace

}  // namespace tribex::cli
