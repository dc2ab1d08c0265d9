// SPDX-License-Identifier: MIT
#include "tools/pstd/output.hpp"

#include <cstdarg>
#include <cstdio>

#include "tools/common/text_file.hpp"

namespace tribex::pstd {

namespace {
/// A CSV file built in memory and written in one go by tools::write_text_file (nothing half-written).
struct Text {
  std::string text;
  __attribute__((format(printf, 2, 3))) void printf(const char* format, ...) {
    std::va_list args, copy;
    va_start(args, format);
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    const std::size_t old = text.size();
    text.resize(old + static_cast<std::size_t>(n) + 1);
    std::vsnprintf(text.data() + old, static_cast<std::size_t>(n) + 1, format, args);
    text.resize(old + static_cast<std::size_t>(n));
    va_end(args);
  }
};
constexpr double nm = 1e9, uN = 1e6, um2 = 1e12;
}  // namespace

std::vector<ContactReport> initial_contacts(const Model& model, double normal_force) {
  Gap gap(model);
  gap.set_travel(0);
  const double h = height_for_force(gap, normal_force, 1e-10);
  std::vector<ContactReport> out;
  for (const auto& s : gap.summits()) {
    const double delta = s.d - h;
    if (!(delta > 0.0)) break;
    ContactReport c;
    c.copy = model.segments[s.segment].copy;
    c.segment = s.segment;
    c.x = model.dx * static_cast<double>((model.segments[s.segment].start + s.index) % model.substrate.size());
    c.interference = delta;
    c.radius = s.radius;
    const auto& mech = model.mechanics;
    if (mech.law == ContactLaw::line_2d) {
      c.half_width = line_contact_half_width(delta, s.radius);
      c.force = mech.depth * line_contact_load(c.half_width, s.radius, mech.modulus);
    } else {
      c.half_width = hertz_half_width(delta, s.radius);
      c.force = hertz_load(delta, s.radius, mech.modulus);
    }
    out.push_back(c);
  }
  return out;
}

void write_trajectory_csv(const std::string& path, const Run& run, const std::vector<PstdEvent>& events) {
  Text out;
  out.printf(
             "position[nm],displacement[um],normal_force_arrival[uN],normal_force[uN],restoring_force[uN],shear_capacity[uN],"
             "contacts,true_area[um^2],mean_half_width[nm],max_interference[nm],lifted,pstd_event\n");
  std::size_t e = 0;
  for (std::size_t i = 0; i < run.steps.size(); ++i) {
    const auto& s = run.steps[i];
    while (e < events.size() && events[e].last < i) ++e;
    const int event = (e < events.size() && events[e].first <= i) ? static_cast<int>(e) + 1 : 0;
    out.printf( "%.3f,%.6f,%.9g,%.9g,%.9g,%.9g,%d,%.9g,%.6g,%.6g,%d,%d\n", s.position * nm, s.displacement * 1e6,
               s.normal_force_arrival * uN, s.normal_force * uN, s.restoring * uN, s.capacity * uN, s.contacts,
               s.area * um2, s.mean_half_width * nm, s.max_interference * nm, s.lifted ? 1 : 0, event);
  }
  tools::write_text_file(path, out.text);
}

void write_events_csv(const std::string& path, const std::vector<PstdEvent>& events) {
  Text out;
  out.printf(
             "event,start[nm],end[nm],length[nm],lifts,normal_force_start[uN],normal_force_end[uN],"
             "true_area_start[um^2],true_area_end[um^2],contacts_min,contacts_max,mean_half_width[nm]\n");
  for (std::size_t i = 0; i < events.size(); ++i) {
    const auto& e = events[i];
    out.printf( "%zu,%.3f,%.3f,%.3f,%zu,%.9g,%.9g,%.9g,%.9g,%d,%d,%.6g\n", i + 1, e.start * nm, e.end * nm,
               (e.end - e.start) * nm, e.lifts, e.force_start * uN, e.force_end * uN, e.area_start * um2,
               e.area_end * um2, e.contacts_min, e.contacts_max, e.half_width * nm);
  }
  tools::write_text_file(path, out.text);
}

void write_contacts_csv(const std::string& path, const std::vector<ContactReport>& contacts) {
  Text out;
  out.printf( "copy,segment,x[nm],interference[nm],radius[nm],half_width[nm],force[uN]\n");
  for (const auto& c : contacts)
    out.printf( "%d,%zu,%.3f,%.6g,%.6g,%.6g,%.9g\n", c.copy, c.segment, c.x * nm, c.interference * nm,
               c.radius * nm, c.half_width * nm, c.force * uN);
  tools::write_text_file(path, out.text);
}

void write_study_csv(const std::string& path, const std::vector<StudyRow>& rows) {
  Text out;
  out.printf(
             "copies,apparent_length[um],normal_force[uN],initial_contacts,initial_true_area[um^2],pstd_events,"
             "final_normal_force[uN],wall_time[s]\n");
  for (const auto& r : rows)
    out.printf( "%zu,%.6g,%.9g,%d,%.9g,%zu,%.9g,%.3f\n", r.copies, r.apparent_length * 1e6,
               r.normal_force * uN, r.run.initial_contacts, r.run.initial_area * um2, r.events.size(),
               r.run.steps.back().normal_force * uN, r.wall_seconds);
  tools::write_text_file(path, out.text);
}

void write_study_trajectories_csv(const std::string& path, const std::vector<StudyRow>& rows) {
  Text out;
  out.printf( "copies,position[nm],normal_force[uN],contacts\n");
  for (const auto& r : rows)
    for (const auto& s : r.run.steps)
      out.printf( "%zu,%.3f,%.9g,%d\n", r.copies, s.position * nm, s.normal_force * uN, s.contacts);
  tools::write_text_file(path, out.text);
}

}  // namespace tribex::pstd
