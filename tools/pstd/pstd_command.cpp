// SPDX-License-Identifier: MIT
// `tribex pstd`: the pre-sliding tangential deflection model of the seed report, Section 2.1.9.
// Builds the substrate and counterface profiles, runs the quasi-static stepping (tools/pstd/stepping.hpp),
// detects PSTD events (events.hpp), and writes CSV, JSON and PNG plots into the output folder.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "mesh/afm/height_map.hpp"
#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"
#include "tools/common/json.hpp"
#include "tools/common/text_file.hpp"
#include "tools/pstd/counterface.hpp"
#include "tools/pstd/events.hpp"
#include "tools/pstd/output.hpp"
#include "tools/pstd/profile_sources.hpp"
#include "tools/pstd/stepping.hpp"

namespace tribex::cli {

namespace {

const char* usage =
    "usage: tribex pstd [options]\n"
    "\n"
    "Quasi-static 2-D model of pre-sliding tangential deflection (seed report, Section 2.1.9): a rigid\n"
    "counterface of linked line scans is pressed onto a substrate line to a normal force; it advances 1 grid\n"
    "step whenever the restoring force exceeds the shear capacity tau*A, otherwise it is lifted (normal force\n"
    "reduced) until it does. Lengths and forces take units (10nm, 2um, 50uN); plain numbers are SI.\n"
    "Worked example (a real AFM line, the apparent-area study): tools/pstd/README.md.\n"
    "\n"
    "profiles (default: seeded synthetic Gaussian-correlated lines):\n"
    "  --afm FILE              AFM height map (Nanoscope .di/.spm/.000, Gwyddion .gsf or ASCII matrix, x y z\n"
    "                          text; mesh/afm): substrate = a row (scan direction), segments = columns\n"
    "  --channel N             image channel of a multi-channel --afm file (default: the first height channel)\n"
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
  const long channel = a.integer("--channel", -1);
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
  if (channel != -1 && !afm) throw tools::BadInput("tribex pstd: --channel selects a channel of --afm; add --afm FILE");
  if (line < -1 || channel < -1 || channel > 1000)
    throw tools::BadInput("tribex pstd: --line and --channel count from 0 (--channel at most 1000)");
  if (!(rms >= 0) || !(corr > 0) || !(source_dx > 0) || !(substrate_length > 0))
    throw tools::BadInput("tribex pstd: --rms must be >= 0 and --corr, --source-dx, --substrate-length > 0");
  if (source_dx < dx) throw tools::BadInput("tribex pstd: --source-dx must not be finer than --sampling");
  // Bounded before anything is allocated (issue 54, item 12; pstd::kMaxProfileSamples, tools/pstd/README.md).
  if (!afm && !substrate_file)
    pstd::check_sample_count(substrate_length / source_dx,
                             "the synthetic substrate (--substrate-length " + tools::json_number(substrate_length) +
                                 " m at --source-dx " + tools::json_number(source_dx) + " m)",
                             "choose a shorter --substrate-length or a coarser --source-dx");
  pstd::check_sample_count(segment_length / dx * static_cast<double>(segments),
                           "the counterface (--segments " + std::to_string(segments) + " x --segment-length " +
                               tools::json_number(segment_length) + " m at --sampling " + tools::json_number(dx) + " m)",
                           "choose a coarser --sampling, fewer --segments or a shorter --segment-length");

  Profiles p;
  const auto k_segments = static_cast<std::size_t>(segments);
  if (afm) {
    // Any format mesh/afm reads; its errors are mesh::MeshError naming file:line or byte (exit code 2).
    const mesh::afm::HeightMap map = mesh::afm::read_height_map(*afm, static_cast<int>(channel));
    if (line >= static_cast<long>(map.ny))
      throw tools::BadInput("tribex pstd: --line " + std::to_string(line) + " is beyond the " +
                            std::to_string(map.ny) + " rows of " + *afm + " (use 0.." + std::to_string(map.ny - 1) + ")");
    const std::size_t row = line >= 0 ? static_cast<std::size_t>(line) : pstd::seeded_index(seed, 0, map.ny);
    pstd::RawProfile sub = pstd::map_row(map, row);
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
      p.segments.push_back(pstd::window_fine(pstd::map_column(map, col), start, segment_length, dx, true));
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


}  // namespace

int pstd_command(const std::vector<std::string>& args) {
  namespace dim = inputs::dim;
  tools::Args a(args, "tribex pstd", usage, {"--study", "--no-plots", "--quiet"});
  if (a.answered_help()) return tools::exit_ok;
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
  if (a.positional_count() > 0)
    throw tools::BadInput("tribex pstd: unexpected argument '" + *a.optional_positional(0) +
                          "'; pstd takes options only (the worked example is in tools/pstd/README.md)");

  pstd::Mechanics mech;
  mech.law = law == "2d" ? pstd::ContactLaw::line_2d : pstd::ContactLaw::hertz_3d;
  mech.modulus = pstd::effective_modulus(e, nu, e, nu);
  mech.depth = depth;
  mech.shear_strength = tau;
  const double substrate_length = profiles.substrate.length();
  const double travel = travel_arg ? *travel_arg : substrate_length;
  if (!(travel >= 0) || travel > substrate_length * (1 + 1e-12))
    throw tools::BadInput("tribex pstd: --travel must be between 0 and the substrate length (" +
                          tools::json_number(substrate_length * 1e6) + " um)");
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
    using tools::json_number;
    using tools::json_string;
    std::string segs;
    for (const auto& s : profiles.segments) segs += (segs.empty() ? "" : ", ") + json_string(s.origin);
    const std::pair<const char*, std::string> fields[] = {
        {"model", json_string("pstd")},
        {"law", json_string(law)},
        {"seed", std::to_string(seed)},
        {"substrate", json_string(profiles.substrate.origin)},
        {"counterface_segments", "[" + segs + "]"},
        {"substrate_length_um", json_number(substrate_length * 1e6)},
        {"counterface_length_um", json_number(counterface_length * 1e6)},
        {"sampling_nm", json_number(dx * 1e9)},
        {"curvature_span_nm", json_number(static_cast<double>(main_model.curvature_span) * dx * 1e9)},
        {"effective_modulus_GPa", json_number(mech.modulus * 1e-9)},
        {"depth_um", json_number(depth * 1e6)},
        {"tau_MPa", json_number(tau * 1e-6)},
        {"copies", std::to_string(main.copies)},
        {"normal_force_uN", json_number(main.normal_force * 1e6)},
        {"travel_um", json_number(travel * 1e6)},
        {"initial_contacts", std::to_string(main.run.initial_contacts)},
        {"initial_true_area_um2", json_number(main.run.initial_area * 1e12)},
        {"final_normal_force_uN", json_number(main.run.steps.back().normal_force * 1e6)},
        {"reference_half_width_nm", json_number(a_ref * 1e9)},
        {"pstd_events", std::to_string(main.events.size())},
        {"contacts_beyond_2d_law_range", std::to_string(main.run.clamped_contacts)},
        {"wall_time_s", json_number(main.wall_seconds)},
    };
    std::string json = "{";
    for (const auto& [key, value] : fields) json += std::string(json.size() > 1 ? ",\n  " : "\n  ") + json_string(key) + ": " + value;
    tools::write_text_file(dir + "summary.json", json + "\n}\n");
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

}  // namespace tribex::cli
