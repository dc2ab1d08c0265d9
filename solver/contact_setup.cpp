// SPDX-License-Identifier: MIT
#include "solver/contact_setup.hpp"

#include <algorithm>
#include <cmath>

#include "inputs/did_you_mean.hpp"
#include "solver/errors.hpp"
#include "solver/model.hpp"
#include "solver/output/run_log.hpp"

namespace tribex::solver {

std::unique_ptr<contact::ContactManager> build_contact(const inputs::ContactSpec& spec, const Model& model, double dt,
                                                       std::vector<std::string>* report) {
  const auto& mesh = model.mesh;
  std::vector<std::string> known;
  for (const auto& [name, sides] : mesh.side_sets) known.push_back(name);
  std::vector<contact::ContactSurface> surfaces;
  std::vector<std::string> names;
  for (const auto& s : spec.surfaces) {
    for (const auto& set : s.side_sets) {
      auto it = mesh.side_sets.find(set);
      if (it == mesh.side_sets.end()) {
        const std::string hint = inputs::closest_match(set, known);
        throw SetupError(s.where.str() + ": error: contact surface '" + s.name + "' names side set '" + set +
                         "', which is not in the mesh" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      if (it->second.empty()) throw SetupError(s.where.str() + ": error: side set '" + set + "' is empty");
    }
    surfaces.push_back(contact::make_surface(mesh, s.name, s.side_sets));
    names.push_back(s.name);
  }
  auto index_of = [&](const std::string& n) {
    return static_cast<int>(std::find(names.begin(), names.end(), n) - names.begin());
  };
  std::vector<contact::InteractionSettings> interactions;
  for (const auto& it : spec.interactions) {
    contact::InteractionSettings s;
    s.name = it.name;
    s.slave = index_of(it.slave);
    s.master = index_of(it.master);
    s.symmetric = it.symmetric;
    s.penalty_scale = spec.penalty_scale_factor;
    s.search_margin = spec.search_margin.value_or(0.0);
    interactions.push_back(s);
  }
  auto manager = std::make_unique<contact::ContactManager>(std::move(surfaces), std::move(interactions), model.mass, dt,
                                                           mesh.node_count());
  if (spec.axis) manager->set_axis(spec.axis->data(), spec.axis->data() + 3);

  // Pre-flight: initial gaps and overlaps per pass, worst nodes named.
  const auto overlaps = manager->initial_overlaps(mesh.coordinates.data(), 3);
  double mean_edge = 0.0;
  for (const auto& s : manager->surfaces()) mean_edge = std::max(mean_edge, s.mean_edge);
  const double tolerance = spec.initial_overlap_tolerance.value_or(0.01 * mean_edge);
  std::string worst;
  for (const auto& o : overlaps) {
    if (report)
      report->push_back(format("  initial gap %s: node %d gap %.4g m", o.pass.c_str(), o.node + 1, o.gap));
    if (-o.gap > tolerance)
      worst += format("%snode %d (%s) overlaps by %.4g m", worst.empty() ? "" : "; ", o.node + 1, o.pass.c_str(), -o.gap);
  }
  if (!worst.empty())
    throw SetupError(spec.where.str() + ": error: bodies overlap at t = 0 beyond the tolerance " + format("%.3g m", tolerance) +
                     ": " + worst + "; move the bodies apart or set 'initial overlap tolerance'");
  return manager;
}

}  // namespace tribex::solver
