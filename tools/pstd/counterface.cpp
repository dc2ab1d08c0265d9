// SPDX-License-Identifier: MIT
#include "tools/pstd/counterface.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "tools/common/errors.hpp"

namespace tribex::pstd {

Model build_model(const Profile& substrate, const std::vector<Profile>& segments, std::size_t copies,
                  const Mechanics& mechanics) {
  Model model;
  model.dx = substrate.dx;
  model.substrate = substrate.z;
  model.mechanics = mechanics;
  const std::size_t n = substrate.z.size();
  std::size_t counterface_samples = 0;
  double source_dx = substrate.source_dx;
  for (const auto& s : segments) {
    counterface_samples += s.z.size();
    source_dx = std::max(source_dx, s.source_dx);
  }
  if (counterface_samples > n)
    throw tools::BadInput("tribex pstd: the counterface (" + std::to_string(counterface_samples * model.dx * 1e6) +
                          " um) is longer than the substrate (" + std::to_string(n * model.dx * 1e6) +
                          " um); use fewer --segments or a shorter --segment-length");
  // Curvature stencil over one source spacing: finer than that the oversampled lines are piecewise linear.
  model.curvature_span = std::max(1, static_cast<int>(std::lround(source_dx / model.dx)));
  for (std::size_t j = 0; j < copies; ++j) {
    std::size_t start = (j * n) / copies;
    for (const auto& s : segments) {
      model.segments.push_back(place_in_point_contact(model.substrate, s.z, start, static_cast<int>(j)));
      start += s.z.size();
    }
  }
  return model;
}

}  // namespace tribex::pstd
