// SPDX-License-Identifier: MIT
#include "solver/contact_setup.hpp"

#include <algorithm>
#include <cmath>

#include "inputs/did_you_mean.hpp"
#include "solver/errors.hpp"
#include "solver/model.hpp"
#include "solver/output/run_log.hpp"

namespace tribex::solver {
namespace {

// The default adhesion cut-off h_c = 20 z0 keeps 99.03 % of W (docs/theory.md 6.3; 5 z0 keeps 86.1 %,
// 10 z0 96.3 %); a cut-off keeping less than 99 % is a set-up warning.
constexpr double default_cutoff_in_z0 = 20.0;
constexpr double kept_work_warning = 0.99;

// Adhesion / junction parameters (docs/theory.md 6, 7) with their defaults, the capture distance of the
// search raised to the adhesion cut-off gap; each choice goes to the run log.
void interface_model(const inputs::InteractionSpec& it, const inputs::ContactSpec& spec,
                     const contact::ContactSurface& slave, const contact::ContactSurface& master,
                     const std::vector<double>& mass, double dt, contact::InteractionSettings& s,
                     std::vector<std::string>* report, SetupFindings* findings) {
  auto log = [&](const std::string& line) {
    if (report) report->push_back("  interaction " + it.name + ": " + line);
  };
  const bool junction = it.model == inputs::InteractionModel::junction;
  s.model = junction ? contact::InterfaceModel::junction : contact::InterfaceModel::adhesion;
  s.adhesion.work = it.work_of_adhesion;
  s.adhesion.z0 = it.equilibrium_separation;
  s.adhesion.cutoff = it.adhesion_cutoff.value_or(default_cutoff_in_z0 * it.equilibrium_separation);
  s.junction.gap_tolerance = it.junction_gap_tolerance.value_or(0.05 * it.equilibrium_separation);
  log(format("adhesion W = %.4g J/m^2, z0 = %.4g m, cutoff h_c = %.4g m (%.3g z0%s), captured work %.4g J/m^2 "
             "(%.2f %% of W), in contact when gap <= %.4g m",
             s.adhesion.work, s.adhesion.z0, s.adhesion.cutoff, s.adhesion.cutoff / s.adhesion.z0,
             it.adhesion_cutoff ? "" : ", the default", contact::captured_work(s.adhesion),
             100.0 * contact::captured_work(s.adhesion) / s.adhesion.work, s.junction.gap_tolerance));
  const double kept = contact::captured_work(s.adhesion) / s.adhesion.work;
  if (findings && kept < kept_work_warning) {
    RunWarning w;
    w.kind = WarningKind::adhesion_cutoff;
    w.value = w.max_value = kept;
    w.threshold = kept_work_warning;
    w.message = format("%s: interaction '%s': 'adhesion cutoff' %.4g m (%.3g z0) keeps %.1f %% of the work of "
                       "adhesion W = %.4g J/m^2 (pull-off and adhesion energy fall short by as much); set 'adhesion "
                       "cutoff = %.4g m' (20 z0, 99.0 %%) or remove it for the default",
                       it.where.str().c_str(), it.name.c_str(), s.adhesion.cutoff, s.adhesion.cutoff / s.adhesion.z0,
                       100 * kept, s.adhesion.work, default_cutoff_in_z0 * s.adhesion.z0);
    findings->warnings.push_back(w);
  }
  // The search must capture every pair within the cut-off gap g_c, not only penetrating ones.
  const double g_c = s.adhesion.capture_gap();
  const double margin = s.search_margin > 0 ? s.search_margin : master.mean_edge;
  if (margin < g_c) {
    if (spec.search_margin)
      throw SetupError(spec.where.str() + ": error: 'search margin' " + format("%.4g m", margin) +
                       " is below the adhesion cut-off gap h_c - z0 = " + format("%.4g m", g_c) + " of interaction '" +
                       it.name + "'; raise 'search margin' to at least that or lower 'adhesion cutoff'");
    s.search_margin = g_c;
    log(format("search margin raised from the mean face edge %.4g m to the cut-off gap %.4g m", margin, g_c));
  }
  if (!junction) return;
  s.junction.strength = it.junction_strength;
  s.junction.reference_speed = it.junction_reference_speed.value_or(0.1);
  // The shear is taken backward-Euler per pair (contact/models/junction_shear.hpp, docs/theory.md 7.3),
  // so v_ref has no stability floor. For the record, the floor an explicit tanh damper
  // c = tau* A_I / v_ref would need, c dt / m_eff < 2, estimated with the median master node mass.
  std::vector<double> master_mass;
  for (int node : master.nodes) master_mass.push_back(mass[node]);
  std::nth_element(master_mass.begin(), master_mass.begin() + master_mass.size() / 2, master_mass.end());
  const double m_master = master_mass[master_mass.size() / 2];
  double v_explicit = 0.0;
  for (int k = 0; k < slave.node_count(); ++k) {
    const double ms = mass[slave.nodes[k]];
    const double m_eff = ms * m_master / (ms + m_master);
    v_explicit = std::max(v_explicit, s.junction.strength * slave.node_area[k] * dt / (2.0 * m_eff));
  }
  log(format("junction strength tau* = %.4g Pa, reference speed %.4g m/s (tanh law, backward Euler per pair: no "
             "stability floor; an explicit update would need v_ref > %.4g m/s)",
             s.junction.strength, s.junction.reference_speed, v_explicit));
}

// Mean P-wave modulus M = lambda + 2 mu (reference state) of the elements under a contact surface's
// faces, Pa: the stiffness that decides which side of a node-to-face pair may carry the point loads.
double surface_wave_modulus(const Model& model, const inputs::ContactSurfaceSpec& surface) {
  double sum = 0.0;
  long count = 0;
  for (const auto& set : surface.side_sets)
    for (const auto& side : model.mesh.side_sets.at(set))
      for (const auto& b : model.blocks)
        if (side.element >= b.first_element && side.element < b.first_element + b.count) {
          sum += materials::wave_modulus_of(b.material);
          ++count;
          break;
        }
  return count ? sum / static_cast<double>(count) : 0.0;
}

// Node-to-face penalty puts its point loads on the master's nodes. A master much softer than the
// slave folds under them, and the contact then injects energy (issue 22: a Si sphere on a SAM
// coating as master, up to 2 % after the kink fix, none with the roles swapped); production codes
// advise the softer body as slave for the same reason. So for one-pass node-to-face pairs whose
// slave is more than twice as stiff (P-wave modulus) as the master, the roles are swapped and the
// run log says so. Mortar and two-pass pairs keep the deck's order.
constexpr double stiffer_slave_ratio = 2.0;

void order_roles(const inputs::InteractionSpec& it, const inputs::ContactSpec& spec, const Model& model,
                 contact::InteractionSettings& s, std::vector<std::string>* report) {
  if (it.symmetric || it.enforcement == inputs::InteractionEnforcement::mortar ||
      it.model == inputs::InteractionModel::rough_surface)
    return;
  const auto& slave = spec.surfaces[static_cast<std::size_t>(s.slave)];
  const auto& master = spec.surfaces[static_cast<std::size_t>(s.master)];
  const double m_slave = surface_wave_modulus(model, slave), m_master = surface_wave_modulus(model, master);
  if (!(m_slave > stiffer_slave_ratio * m_master)) return;
  std::swap(s.slave, s.master);
  if (report)
    report->push_back(format("  interaction %s: slave '%s', master '%s' (swapped from the deck's order): '%s' is the "
                             "softer side (M = %.4g GPa against %.4g GPa), and node-to-face contact on a soft master "
                             "injects energy (contact/README.md); write 'surfaces = %s %s' to say so in the deck",
                             it.name.c_str(), master.name.c_str(), slave.name.c_str(), master.name.c_str(),
                             m_master * 1e-9, m_slave * 1e-9, master.name.c_str(), slave.name.c_str()));
}

// One-point (mean-quadrature) elements under node-to-face penalty contact: at high contact pressure the
// point forces excite the elements' hourglass modes; contact work turns negative and elements invert
// (verification/hertz/README.md, "Element choice"). Recorded for the run guards, which raise it once
// the penetration shows such a pressure (flat contacts at low pressure run fine on these elements).
void note_one_point_elements(const inputs::InteractionSpec& it, const inputs::ContactSpec& spec, const Model& model,
                             SetupFindings& findings) {
  std::vector<std::string> blocks;
  for (const auto& surface : spec.surfaces) {
    if (surface.name != it.slave && surface.name != it.master) continue;
    for (const auto& set : surface.side_sets)
      for (const auto& side : model.mesh.side_sets.at(set)) {
        const auto& b = model.blocks[static_cast<std::size_t>(model.element_block[static_cast<std::size_t>(side.element)])];
        if (b.formulation == inputs::ElementFormulation::mean_quadrature &&
            std::find(blocks.begin(), blocks.end(), b.name) == blocks.end())
          blocks.push_back(b.name);
      }
  }
  if (blocks.empty()) return;
  std::string text = format("%s: interaction '%s' on block", it.where.str().c_str(), it.name.c_str());
  for (std::size_t k = 0; k < blocks.size(); ++k) text += (k ? ", '" : " '") + blocks[k] + "'";
  findings.one_point_contact += (findings.one_point_contact.empty() ? "" : "; ") + text;
}

// The two surfaces of an interaction must be two bodies' faces: a side set in both would make every
// node its own closest face (no self-contact).
void refuse_shared_side_sets(const inputs::ContactSpec& spec, const inputs::InteractionSpec& it,
                             const inputs::ContactSurfaceSpec& slave, const inputs::ContactSurfaceSpec& master) {
  for (const auto& set : master.side_sets)
    if (std::find(slave.side_sets.begin(), slave.side_sets.end(), set) != slave.side_sets.end()) {
      const auto& later = slave.where.line > master.where.line ? slave : master;
      throw SetupError(later.where.str() + ": error: contact surfaces '" + slave.name + "' and '" + master.name +
                       "' of interaction '" + it.name + "' both contain side set '" + set +
                       "'; a surface cannot contact itself: give each surface the faces of one body" +
                       (spec.name.empty() ? "" : " (contact definition '" + spec.name + "')"));
    }
}

}  // namespace

std::unique_ptr<contact::ContactManager> build_contact(const inputs::ContactSpec& spec, const Model& model, double dt,
                                                       std::vector<std::string>* report,
                                                       SetupFindings* findings) {
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
    refuse_shared_side_sets(spec, it, spec.surfaces[static_cast<std::size_t>(s.slave)],
                            spec.surfaces[static_cast<std::size_t>(s.master)]);
    s.symmetric = it.symmetric;
    order_roles(it, spec, model, s, report);
    if (it.enforcement == inputs::InteractionEnforcement::mortar) {
      s.enforcement = contact::Enforcement::mortar;
      if (report)
        report->push_back("  interaction " + it.name +
                          ": mortar (segment-to-segment) enforcement, penalty per area k_A = s m_A / dt^2" +
                          (it.model == inputs::InteractionModel::adhesion ? ", adhesion at face integration points" : ""));
    }
    s.penalty_scale = spec.penalty_scale_factor;
    s.search_margin = spec.search_margin.value_or(0.0);
    if (it.model == inputs::InteractionModel::rough_surface)
      rough_surface_model(it, spec, surfaces[static_cast<std::size_t>(s.master)], s, report);
    else if (it.model != inputs::InteractionModel::frictionless)
      interface_model(it, spec, surfaces[static_cast<std::size_t>(s.slave)], surfaces[static_cast<std::size_t>(s.master)],
                      model.mass, dt, s, report, findings);
    if (findings && s.enforcement == contact::Enforcement::node_to_face &&
        it.model != inputs::InteractionModel::rough_surface)
      note_one_point_elements(it, spec, model, *findings);
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
