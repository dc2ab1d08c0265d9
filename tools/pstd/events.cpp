// SPDX-License-Identifier: MIT
#include "tools/pstd/events.hpp"

#include <algorithm>

namespace tribex::pstd {

double mean_half_width(const Run& run, std::size_t first, std::size_t last) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = first; i <= last && i < run.steps.size(); ++i)
    if (run.steps[i].contacts > 0) { sum += run.steps[i].mean_half_width; ++n; }
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

double reference_half_width(const Run& run) {
  return run.steps.empty() ? 0.0 : mean_half_width(run, 0, run.steps.size() - 1);
}

std::vector<PstdEvent> detect_pstd(const Run& run, const DetectionRule& rule) {
  std::vector<PstdEvent> events;
  if (run.steps.size() < 2) return events;
  const double dx = run.steps[1].position - run.steps[0].position;

  auto close_group = [&](std::size_t first, std::size_t last, std::size_t lifts) {
    const auto& a = run.steps[first];
    const auto& b = run.steps[last];
    const double half_width = mean_half_width(run, first, last);
    if (lifts < 2 || b.position - a.position < rule.length_factor * half_width * (1.0 - 1e-9)) return;
    PstdEvent e{first, last, a.position, b.position, a.normal_force, b.normal_force, a.area, b.area,
                a.contacts, a.contacts, lifts, half_width};
    for (std::size_t i = first; i <= last; ++i) {
      e.contacts_min = std::min(e.contacts_min, run.steps[i].contacts);
      e.contacts_max = std::max(e.contacts_max, run.steps[i].contacts);
    }
    events.push_back(e);
  };

  bool open = false;
  std::size_t first = 0, last = 0, lifts = 0;
  for (std::size_t i = 0; i < run.steps.size(); ++i) {
    if (!run.steps[i].lifted) continue;
    const double gap = std::max(dx, rule.gap_factor * run.steps[last].mean_half_width) * (1.0 + 1e-9);
    if (open && run.steps[i].position - run.steps[last].position <= gap) {
      last = i;
      ++lifts;
      continue;
    }
    if (open) close_group(first, last, lifts);
    open = true;
    first = last = i;
    lifts = 1;
  }
  if (open) close_group(first, last, lifts);
  return events;
}

}  // namespace tribex::pstd
