// SPDX-License-Identifier: MIT
#include "solver/mass_scaling.hpp"

#include <algorithm>
#include <cmath>

#include "inputs/did_you_mean.hpp"
#include "solver/errors.hpp"
#include "solver/model.hpp"
#include "solver/output/run_log.hpp"
#include "solver/parallel/communicator.hpp"
#include "solver/stable_time_step.hpp"

namespace tribex::solver {

double mass_scale_factor(double element_dt, double element_target) {
  if (!(element_dt < element_target)) return 1.0;
  const double r = element_target / element_dt;
  return r * r;
}

MassScalingReport apply_mass_scaling(const inputs::MassScalingSpec& spec, double time_step_scale_factor,
                                     double maximum_time_step, Model& model) {
  MassScalingReport report;
  report.active = true;
  report.maximum_added_mass_fraction = spec.maximum_added_mass_fraction;
  const mesh::Mesh& m = model.mesh;

  // Which blocks: the deck's list (each must be a block of the mesh) or every block.
  std::vector<std::string> names;
  for (const auto& b : model.blocks) names.push_back(b.name);
  for (const auto& name : spec.blocks)
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      const std::string hint = inputs::closest_match(name, names);
      std::string known;
      for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
      throw SetupError(spec.blocks_where.str() + ": error: 'blocks' of 'begin mass scaling' names block '" + name +
                       "', which is not in the mesh" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)") +
                       "; the mesh has: " + known);
    }

  // The reference estimate of every element (the same one the run starts from).
  std::vector<double> dt_e(static_cast<std::size_t>(m.element_count()));
  const StableStep unscaled = whole_model_stable_time_step(model, dt_e.data());
  report.unscaled_time_step = std::min(time_step_scale_factor * unscaled.dt, maximum_time_step);
  report.target_time_step =
      spec.target_time_step ? *spec.target_time_step : *spec.largest_factor * report.unscaled_time_step;
  const std::string key = spec.target_time_step ? "target time step" : "largest factor";
  if (spec.target_time_step && !(report.target_time_step > report.unscaled_time_step))
    throw SetupError(spec.target_where.str() +
                     format(": error: 'target time step' %.6g s is not above the run's time step without mass scaling, "
                            "%.6g s (time step scale factor %.3g x stable step %.6g s of element %d): nothing to scale; "
                            "raise the target (e.g. %.3g s, twice the unscaled step) or remove 'begin mass scaling'",
                            report.target_time_step, report.unscaled_time_step, time_step_scale_factor, unscaled.dt,
                            unscaled.controlling_element + 1, 2 * report.unscaled_time_step));
  if (report.target_time_step > maximum_time_step)
    throw SetupError(spec.target_where.str() +
                     format(": error: the mass-scaling target %.6g s ('%s') is above 'maximum time step' %.6g s, so the "
                            "run cannot reach it; lower the target or raise 'maximum time step'",
                            report.target_time_step, key.c_str(), maximum_time_step));

  // Per element: s_e = (T_e / dt_e)^2 where dt_e < T_e; dm_e = (s_e - 1) rho V0 to the nodes (1/8 each),
  // this rank's elements to its partial nodal masses (summed over the ranks by build_model), the
  // report's sums over the ranks.
  const double element_target = report.target_time_step / time_step_scale_factor;
  for (auto& blk : model.blocks) {
    BlockMassScaling b;
    b.name = blk.name;
    b.elements = blk.count;
    b.listed = spec.blocks.empty() || std::find(spec.blocks.begin(), spec.blocks.end(), blk.name) != spec.blocks.end();
    const double rho = materials::density_of(blk.material);
    for (int e = 0; e < blk.count; ++e) b.mass += rho * blk.volume0[e];
    if (b.listed) {
      blk.mass_scale.assign(static_cast<std::size_t>(blk.count), 1.0);
      for (int e = 0; e < blk.count; ++e) {
        const int global = blk.first_element + e;
        const double s = mass_scale_factor(dt_e[global], element_target);
        if (s == 1.0) continue;
        blk.mass_scale[e] = s;
        const double added = (s - 1.0) * rho * blk.volume0[e];
        for (int I = 0; I < 8; ++I) model.mass[m.connectivity[8 * global + I]] += added / 8.0;
        b.added_mass += added;
        ++b.scaled_elements;
        b.largest_scale = std::max(b.largest_scale, s);
      }
      if (b.scaled_elements == 0) blk.mass_scale.clear();
    }
    if (!model.domain.serial()) {
      double sums[4] = {b.mass, b.added_mass, double(b.elements), double(b.scaled_elements)};
      parallel::sum(sums, 4);
      b.mass = sums[0];
      b.added_mass = sums[1];
      b.elements = static_cast<int>(sums[2]);
      b.scaled_elements = static_cast<int>(sums[3]);
      b.largest_scale = parallel::max(b.largest_scale);
    }
    report.unscaled_mass += b.mass;
    report.added_mass += b.added_mass;
    report.blocks.push_back(b);
  }
  return report;
}

void warn_scaled_silent_boundaries(const std::vector<inputs::SilentBoundarySpec>& boundaries, Model& model) {
  for (const auto& sb : boundaries) {
    const auto found = model.mesh.side_sets.find(sb.side_set);
    double counts[2] = {0.0, 0.0};  // faces, faces on scaled elements
    double largest = 1.0;
    int block = -1;
    if (found != model.mesh.side_sets.end())
      for (const auto& side : found->second) {
        const int b = model.element_block[static_cast<std::size_t>(side.element)];
        const ElementBlock& blk = model.blocks[static_cast<std::size_t>(b)];
        const double s = blk.mass_scale.empty() ? 1.0 : blk.mass_scale[static_cast<std::size_t>(side.element - blk.first_element)];
        counts[0] += 1.0;
        if (s > 1.0) {
          counts[1] += 1.0;
          if (s > largest) block = b;
          largest = std::max(largest, s);
        }
      }
    parallel::sum(counts, 2);
    const double rank_largest = largest;
    largest = parallel::max(largest);
    // The block of the largest factor, from the rank that holds it (every rank has the same block list).
    block = static_cast<int>(parallel::max(rank_largest == largest && block >= 0 ? double(block) : -1.0));
    if (counts[1] == 0.0 || block < 0) continue;
    const double root = std::sqrt(largest);
    RunWarning w;
    w.kind = WarningKind::scaled_silent_boundary;
    w.value = w.max_value = (root - 1.0) / (root + 1.0);
    w.message = format("%s: silent boundary on side set '%s': %.0f of its %.0f faces lie on mass-scaled elements (largest "
                       "density factor %.3g, block '%s'); their wave impedance is sqrt(s) rho c against the dashpots' "
                       "rho c, so a normally incident wave reflects up to %.3g of its amplitude (docs/theory.md 1.4.1); "
                       "leave that block out of 'blocks' of 'begin mass scaling', or lower the factor",
                       sb.where.str().c_str(), sb.side_set.c_str(), counts[1], counts[0], largest,
                       model.blocks[static_cast<std::size_t>(block)].name.c_str(), w.value);
    model.setup.warnings.push_back(std::move(w));
  }
}

ContactMassRaise raise_contact_node_masses(const std::vector<int>& nodes, const std::vector<double>& unscaled_mass,
                                           double factor, const std::vector<double>& owned, std::vector<double>& mass) {
  ContactMassRaise raised;
  if (!(factor > 1.0)) return raised;
  for (int n : nodes) {
    const double floor = factor * unscaled_mass[n];
    if (!(mass[n] < floor)) continue;
    raised.added_mass += owned[n] * (floor - mass[n]);
    raised.nodes += owned[n] > 0.0;
    mass[n] = floor;
  }
  return raised;
}

std::vector<std::string> MassScalingReport::lines() const {
  std::vector<std::string> out;
  if (!active) return out;
  out.push_back(format("mass scaling: target time step %.6g s (%.3g x the unscaled step %.6g s); added mass %.6g kg = "
                       "%.3g %% of %.6g kg (limit %.3g %%)",
                       target_time_step, target_time_step / unscaled_time_step, unscaled_time_step, added_mass,
                       100 * added_fraction(), unscaled_mass, 100 * maximum_added_mass_fraction));
  for (const auto& b : blocks)
    out.push_back(b.listed ? format("  block %-16s %8d of %d elements scaled, added %.6g kg = %.3g %% of the block's "
                                    "%.6g kg, largest density factor %.3g",
                                    b.name.c_str(), b.scaled_elements, b.elements, b.added_mass, 100 * b.fraction(),
                                    b.mass, b.largest_scale)
                           : format("  block %-16s not scaled (not in 'blocks')", b.name.c_str()));
  if (contact_nodes > 0)
    out.push_back(format("  contact surfaces: %d nodes raised to %.3g x their unscaled mass ((dt / dt_0)^2: the unscaled "
                         "penalty and the nodes' own elements at the scaled step as unscaled), added %.6g kg",
                         contact_nodes, contact_mass_factor, contact_added_mass));
  return out;
}

std::string MassScalingReport::limit_message() const {
  // The largest contributors first, each as a share of the model's mass, so the user sees what to restrict.
  std::vector<std::pair<double, std::string>> parts;
  for (const auto& b : blocks)
    if (b.added_mass > 0.0) parts.emplace_back(b.added_mass, "block '" + b.name + "'");
  if (contact_added_mass > 0.0) parts.emplace_back(contact_added_mass, "the contact surface nodes");
  std::sort(parts.begin(), parts.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  std::string from;
  for (std::size_t k = 0; k < parts.size() && k < 3; ++k)
    from += format("%s%s %.3g %%", k ? ", " : "", parts[k].second.c_str(), 100 * parts[k].first / unscaled_mass);
  return format("mass scaling adds %.6g kg, %.3g %% of the model's %.6g kg, above 'maximum added mass fraction' %.3g %% "
                "(target time step %.6g s, %.3g x the unscaled step): most from %s; the added inertia would change "
                "the response; lower the target (the added mass grows about as its square), restrict 'blocks', or "
                "raise the limit knowingly",
                added_mass, 100 * added_fraction(), unscaled_mass, 100 * maximum_added_mass_fraction,
                target_time_step, target_time_step / unscaled_time_step, from.c_str());
}

}  // namespace tribex::solver
