// SPDX-License-Identifier: MIT
#include "solver/output/summary_writer.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "solver/errors.hpp"
#include "solver/output/json.hpp"

namespace tribex::solver {

namespace {
// JSON has no NaN/inf: null for them; 17 digits so that the figures round-trip.
std::string number(double x) { return json_number(x, 17); }
}  // namespace

void reserve_summary_json(const std::string& path) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) return;
  const std::string blanks(16384, ' ');
  const bool written = std::fwrite(blanks.data(), 1, blanks.size(), f) == blanks.size();
  if (std::fclose(f) != 0 || !written) std::remove(tmp.c_str());
}

void write_summary_json(const std::string& path, const RunSummary& s, const Energies& e, const StableStep& st) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) throw SetupError("cannot write " + path + ": " + std::strerror(errno));
  std::fprintf(f, "{\n");
  std::fprintf(f, "  \"status\": %s,\n  \"exit_code\": %d,\n", json_string(s.status).c_str(), s.exit_code);
  const RunIdentity& id = s.identity;
  std::fprintf(f, "  \"tribex_version\": %s,\n  \"deck\": %s,\n  \"deck_sha256\": %s,\n",
               json_string(id.version).c_str(), json_string(id.deck_path).c_str(),
               id.deck_sha256.empty() ? "null" : json_string(id.deck_sha256).c_str());
  std::fprintf(f, "  \"started\": %s,\n  \"host\": %s,\n", json_string(id.started_utc).c_str(),
               json_string(id.host).c_str());
  std::fprintf(f, "  \"steps\": %ld,\n  \"final_time\": %s,\n", s.steps, number(s.final_time).c_str());
  std::fprintf(f, "  \"nodes\": %d,\n  \"elements\": %d,\n", s.nodes, s.elements);
  std::fprintf(f, "  \"wall_time_s\": %s,\n  \"loop_time_s\": %s,\n", number(s.wall_seconds).c_str(),
               number(s.loop_seconds).c_str());
  std::fprintf(f, "  \"ns_per_element_step\": %s,\n", number(s.ns_per_element_step).c_str());
  // A run resumed from a restart file: this process ran steps first_step..steps (the figures above);
  // the totals add the earlier segments (null when a restart file did not record them).
  std::fprintf(f, "  \"first_step\": %ld,\n  \"total_wall_time_s\": %s,\n  \"total_loop_time_s\": %s,\n",
               s.first_step, number(s.total_wall_seconds).c_str(), number(s.total_loop_seconds).c_str());
  std::fprintf(f, "  \"contact_time_s\": %s,\n", number(s.contact_seconds).c_str());
  std::fprintf(f, "  \"ranks\": %d,\n", s.ranks);
  std::fprintf(f, "  \"communication_time_s\": %s,\n", number(s.communication_seconds).c_str());
  std::fprintf(f, "  \"initial_stable_time_step\": %s,\n  \"controlling_element\": %d,\n", number(st.dt).c_str(),
               st.controlling_element + 1);
  std::fprintf(f, "  \"energy_error\": %s,\n", number(s.energy_error).c_str());
  std::fprintf(f, "  \"energy_unit\": \"J\",\n");
  // The warnings list (solver/guards/README.md): step/time of the first crossing, the value there, the
  // bound, and the largest value with its step/time; node 1-based (null: none).
  std::fprintf(f, "  \"warnings\": [");
  for (std::size_t i = 0; i < s.warnings.size(); ++i) {
    const RunWarning& w = s.warnings[i];
    std::fprintf(f, "%s\n    {\"kind\": %s, \"step\": %ld, \"time\": %s, \"value\": %s, \"threshold\": %s, "
                 "\"max_value\": %s, \"max_step\": %ld, \"max_time\": %s, \"node\": %s, \"message\": %s}",
                 i ? "," : "", json_string(kind_name(w.kind)).c_str(), w.step, number(w.time).c_str(),
                 number(w.value).c_str(), number(w.threshold).c_str(), number(w.max_value).c_str(), w.max_step,
                 number(w.max_time).c_str(), w.node >= 0 ? std::to_string(w.node + 1).c_str() : "null",
                 json_string(w.message).c_str());
  }
  std::fprintf(f, "%s],\n", s.warnings.empty() ? "" : "\n  ");
  std::fprintf(f, "  \"energies\": {\"kinetic\": %s, \"internal\": %s, \"hourglass\": %s, \"external_work\": %s, "
               "\"silent_boundary_dissipation\": %s, \"damping_dissipation\": %s, \"viscous_dissipation\": %s, "
               "\"plastic_dissipation\": %s, \"contact_work\": %s, \"initial\": %s}\n",
               number(e.kinetic).c_str(), number(e.internal).c_str(), number(e.hourglass).c_str(),
               number(e.external_work).c_str(), number(e.silent_boundary_dissipation).c_str(),
               number(e.damping_dissipation).c_str(), number(e.viscous_dissipation).c_str(),
               number(e.plastic_dissipation).c_str(), number(e.contact_work).c_str(), number(e.initial).c_str());
  std::fprintf(f, "}\n");
  // Written whole or not at all: a full disk keeps the earlier summary.json (if any) and says so.
  const bool written = !std::ferror(f);
  const int write_errno = errno;
  if (std::fclose(f) != 0 || !written) {
    const int err = written ? errno : write_errno;
    std::remove(tmp.c_str());
    throw output_failure(path, err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw output_failure(path, errno);
}

}  // namespace tribex::solver
