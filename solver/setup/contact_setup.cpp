// SPDX-License-Identifier: MIT
#include "solver/setup/contact_setup.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include "inputs/did_you_mean.hpp"
#include "solver/errors.hpp"
#include "solver/model.hpp"
#include "solver/output/run_log.hpp"
#include "solver/parallel/bytes.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {
namespace {

// A captured work below 99 % of W (an adhesion cut-off below 20 z0, docs/theory.md 6.3) is a set-up warning.
constexpr double kept_work_warning = 0.99;

// The law of an interaction from the deck's values (contact/laws/), its line in the run log and the
// adhesion cut-off warning.
void set_law(const inputs::InteractionSpec& it, contact::InteractionSettings& s, std::vector<std::string>* report,
             SetupFindings* findings) {
  auto log = [&](const std::string& line) {
    if (report) report->push_back("  interaction " + it.name + ": " + line);
  };
  try {
    s.law = contact::make_law(contact::law_index(it.model), it.values);
  } catch (const contact::LawError& e) {
    throw SetupError(e.located ? std::string(e.what()) : it.where_of(e.key).str() + ": error: " + e.what());
  } catch (const std::invalid_argument& e) {
    throw SetupError(it.where.str() + ": error: interaction '" + it.name + "': " + e.what());
  }
  log(contact::describe(s.law));
  if (const contact::Adhesion* adhesion = contact::adhesion_of(s.law)) {
    const auto& lj = adhesion->lj;
    const double kept = lj.work > 0.0 ? contact::captured_work(lj) / lj.work : 1.0;  // W = 0: nothing to keep
    if (findings && kept < kept_work_warning) {
      RunWarning w;
      w.kind = WarningKind::adhesion_cutoff;
      w.value = w.max_value = kept;
      w.threshold = kept_work_warning;
      w.message = format("%s: interaction '%s': 'adhesion cutoff' %.4g m (%.3g z0) keeps %.1f %% of the work of "
                         "adhesion W = %.4g J/m^2 (pull-off and adhesion energy fall short by as much); set 'adhesion "
                         "cutoff = %.4g m' (20 z0, 99.0 %%) or remove it for the default",
                         it.where.str().c_str(), it.name.c_str(), lj.cutoff, lj.cutoff / lj.z0, 100 * kept, lj.work,
                         contact::Adhesion::default_cutoff_in_z0 * lj.z0);
      findings->warnings.push_back(w);
    }
  }
}

// The search must capture every pair the law acts on, not only penetrating ones: the margin is raised
// to the largest gap the law acts at (its reach: the adhesion cut-off gap, the rough surface's contact
// separation minus its offset).
void cover_reach(const inputs::InteractionSpec& it, const inputs::ContactSpec& spec, const contact::ContactSurface& master,
                 contact::InteractionSettings& s, std::vector<std::string>* report) {
  const double reach = contact::law_reach(s.law);
  const double margin = s.search_margin > 0 ? s.search_margin : master.mean_edge;
  if (margin < reach) {
    if (spec.search_margin)
      throw SetupError(spec.where.str() + ": error: 'search margin' " + format("%.4g m", margin) +
                       " is below the reach " + format("%.4g m", reach) + " of interaction '" + it.name +
                       "' (the largest gap its law acts at: the adhesion cut-off gap h_c - z0, or the rough surface's "
                       "contact separation minus 'mean plane offset'); raise 'search margin' to at least that");
    s.search_margin = reach;
    if (report)
      report->push_back(format("  interaction %s: search margin raised from the mean face edge %.4g m to the law's reach %.4g m",
                               it.name.c_str(), margin, reach));
  }
}

// Mean P-wave modulus M = lambda + 2 mu (reference state) of the elements under a contact surface's
// faces, Pa: the stiffness that decides which side of a node-to-face pair may carry the point loads.
double surface_wave_modulus(std::span<const double> block_modulus, const ContactFaces& faces,
                            const inputs::ContactSurfaceSpec& surface) {
  double sum = 0.0;
  long count = 0;
  for (const auto& set : surface.side_sets) {
    const auto it = faces.face_block.find(set);
    if (it == faces.face_block.end()) continue;  // missing from the mesh: build_contact says so
    for (int b : it->second)
      if (b >= 0) {
        sum += block_modulus[static_cast<std::size_t>(b)];
        ++count;
      }
  }
  return count ? sum / static_cast<double>(count) : 0.0;
}

const inputs::ContactSurfaceSpec* surface_named(const inputs::ContactSpec& spec, const std::string& name) {
  for (const auto& s : spec.surfaces)
    if (s.name == name) return &s;
  return nullptr;
}

// Node-to-face penalty puts its point loads on the master's nodes. A master much softer than the
// slave folds under them, and the contact then injects energy (issue 22: a Si sphere on a SAM
// coating as master, up to 2 % after the kink fix, none with the roles swapped); production codes
// advise the softer body as slave for the same reason. So for one-pass node-to-face pairs whose
// slave is more than twice as stiff (P-wave modulus) as the master, the roles are swapped and the
// run log says so. Mortar and two-pass pairs keep the deck's order.
constexpr double stiffer_slave_ratio = 2.0;

void order_roles(const inputs::InteractionSpec& it, const inputs::ContactSpec& spec, std::span<const double> block_modulus,
                 const ContactFaces& faces, contact::InteractionSettings& s, std::vector<std::string>* report) {
  if (!runs_swapped(it, spec, faces, block_modulus)) return;
  const auto& slave = spec.surfaces[static_cast<std::size_t>(s.slave)];
  const auto& master = spec.surfaces[static_cast<std::size_t>(s.master)];
  const double m_slave = surface_wave_modulus(block_modulus, faces, slave);
  const double m_master = surface_wave_modulus(block_modulus, faces, master);
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
                             const ContactFaces& faces, SetupFindings& findings) {
  std::vector<std::string> blocks;
  for (const auto& surface : spec.surfaces) {
    if (surface.name != it.slave && surface.name != it.master) continue;
    for (const auto& set : surface.side_sets)
      for (int index : faces.face_block.at(set)) {
        if (index < 0) continue;
        const auto& b = model.blocks[static_cast<std::size_t>(index)];
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

ContactFaces contact_faces(const mesh::Mesh& mesh, const inputs::ContactSpec& spec) {
  std::vector<int> block(static_cast<std::size_t>(mesh.element_count()), -1);
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    for (int e = 0; e < mesh.blocks[b].element_count; ++e)
      block[static_cast<std::size_t>(mesh.blocks[b].first_element + e)] = static_cast<int>(b);
  ContactFaces faces;
  for (const auto& [name, sides] : mesh.side_sets) {
    faces.face_nodes[name];
    faces.face_block[name];
  }
  // Faces in whole-mesh nodes first, then renumbered by ascending node.
  for (const auto& s : spec.surfaces)
    for (const auto& set : s.side_sets) {
      auto it = mesh.side_sets.find(set);
      if (it == mesh.side_sets.end() || !faces.face_block[set].empty()) continue;  // missing: build_contact says so
      for (const auto& side : it->second) {
        const auto n = mesh.side_nodes(side);
        faces.face_nodes[set].insert(faces.face_nodes[set].end(), n.begin(), n.end());
        faces.face_block[set].push_back(block[static_cast<std::size_t>(side.element)]);
        faces.global_node.insert(faces.global_node.end(), n.begin(), n.end());
      }
    }
  std::sort(faces.global_node.begin(), faces.global_node.end());
  faces.global_node.erase(std::unique(faces.global_node.begin(), faces.global_node.end()), faces.global_node.end());
  for (auto& [name, nodes] : faces.face_nodes)
    for (int& n : nodes)
      n = static_cast<int>(std::lower_bound(faces.global_node.begin(), faces.global_node.end(), n) - faces.global_node.begin());
  faces.coordinates.reserve(3 * faces.global_node.size());
  for (int n : faces.global_node)
    for (int i = 0; i < 3; ++i) faces.coordinates.push_back(mesh.coordinates[3 * static_cast<std::size_t>(n) + i]);
  return faces;
}

ContactFaces contact_faces(const mesh::GeneratedPlan& plan, const inputs::ContactSpec& spec) {
  // The mesh of the surfaces' elements: its sets restricted to them keep the contact's side sets whole
  // (in their order), its nodes ascend with the global numbers, so the faces map back one to one.
  std::vector<int> elements;
  for (const auto& s : spec.surfaces)
    for (const auto& set : s.side_sets)
      if (const auto it = plan.side_sets.find(set); it != plan.side_sets.end())
        for (const auto& side : it->second) elements.push_back(side.element);
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  std::vector<int> global_node;
  ContactFaces faces = contact_faces(mesh::generate_elements(plan, elements, global_node), spec);
  for (int& n : faces.global_node) n = global_node[static_cast<std::size_t>(n)];
  return faces;
}

void broadcast_contact_faces(ContactFaces& faces) {
  if (parallel::size() == 1) return;
  std::vector<char> bytes;
  if (parallel::is_root()) {
    parallel::ByteWriter w;
    w.values(faces.global_node);
    w.values(faces.coordinates);
    w.count(faces.face_nodes.size());
    for (const auto& [name, nodes] : faces.face_nodes) {
      w.text(name);
      w.values(nodes);
      w.values(faces.face_block.at(name));
    }
    bytes = std::move(w.bytes);
  }
  parallel::broadcast_bytes(bytes, 0);
  if (parallel::is_root()) return;
  parallel::ByteReader r(bytes);
  faces = {};
  faces.global_node = r.values<int>();
  faces.coordinates = r.values<double>();
  for (std::size_t k = r.count(); k > 0; --k) {
    const std::string name = r.text();
    faces.face_nodes[name] = r.values<int>();
    faces.face_block[name] = r.values<int>();
  }
}

bool runs_swapped(const inputs::InteractionSpec& it, const inputs::ContactSpec& spec, const ContactFaces& faces,
                  std::span<const double> block_modulus) {
  const int law = contact::law_index(it.model);  // -1 (no model): make_law's default, the variant's first law
  const bool penalty = law < 0 ? contact::uses_penalty(contact::ContactLaw{}) : contact::law_info(law).penalty;
  if (it.symmetric || it.enforcement == inputs::InteractionEnforcement::mortar || !penalty) return false;
  const auto* slave = surface_named(spec, it.slave);
  const auto* master = surface_named(spec, it.master);
  if (!slave || !master) return false;
  return surface_wave_modulus(block_modulus, faces, *slave) >
         stiffer_slave_ratio * surface_wave_modulus(block_modulus, faces, *master);
}

inputs::ContactSpec as_enforced(inputs::ContactSpec spec, const ContactFaces& faces, std::span<const double> block_modulus) {
  for (auto& it : spec.interactions)
    if (runs_swapped(it, spec, faces, block_modulus)) std::swap(it.slave, it.master);
  return spec;
}

std::unique_ptr<contact::ContactManager> build_contact(const inputs::ContactSpec& spec, const Model& model,
                                                       const ContactGeometry& geometry, double dt,
                                                       std::vector<std::string>* report,
                                                       SetupFindings* findings) {
  const ContactFaces& faces = geometry.faces;
  std::vector<std::string> known;
  for (const auto& [name, nodes] : faces.face_nodes) known.push_back(name);
  std::vector<contact::ContactSurface> surfaces;
  std::vector<std::string> names;
  for (const auto& s : spec.surfaces) {
    std::vector<int> face_nodes;
    for (const auto& set : s.side_sets) {
      auto it = faces.face_nodes.find(set);
      if (it == faces.face_nodes.end()) {
        const std::string hint = inputs::closest_match(set, known);
        throw SetupError(s.where.str() + ": error: contact surface '" + s.name + "' names side set '" + set +
                         "', which is not in the mesh" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
      }
      if (it->second.empty()) throw SetupError(s.where.str() + ": error: side set '" + set + "' is empty");
      face_nodes.insert(face_nodes.end(), it->second.begin(), it->second.end());
    }
    surfaces.push_back(contact::make_surface(s.name, faces.coordinates.data(), std::move(face_nodes)));
    names.push_back(s.name);
  }
  auto index_of = [&](const std::string& n) {
    return static_cast<int>(std::find(names.begin(), names.end(), n) - names.begin());
  };
  std::vector<double> block_modulus;
  for (const auto& b : model.blocks) block_modulus.push_back(materials::wave_modulus_of(b.material));
  std::vector<contact::InteractionSettings> interactions;
  for (const auto& it : spec.interactions) {
    contact::InteractionSettings s;
    s.name = it.name;
    s.slave = index_of(it.slave);
    s.master = index_of(it.master);
    refuse_shared_side_sets(spec, it, spec.surfaces[static_cast<std::size_t>(s.slave)],
                            spec.surfaces[static_cast<std::size_t>(s.master)]);
    s.symmetric = it.symmetric;
    s.penalty_scale = spec.penalty_scale_factor;
    s.force_along_axis = it.force_along_axis;
    s.search_margin = spec.search_margin.value_or(0.0);
    set_law(it, s, report, findings);
    if (report && s.force_along_axis)
      report->push_back("  interaction " + it.name + ": penalty force along the contact axis (force direction = axis: "
                        "the small-slope contact of the half-space theories, contact/README.md)");
    order_roles(it, spec, block_modulus, faces, s, report);
    cover_reach(it, spec, surfaces[static_cast<std::size_t>(s.master)], s, report);
    if (it.enforcement == inputs::InteractionEnforcement::mortar) {
      s.enforcement = contact::Enforcement::mortar;
      if (report)
        report->push_back("  interaction " + it.name +
                          ": mortar (segment-to-segment) enforcement, penalty per area k_A = s m_A / dt^2" +
                          (contact::adhesion_of(s.law) ? ", adhesion at face integration points" : ""));
    }
    if (findings && s.enforcement == contact::Enforcement::node_to_face && contact::uses_penalty(s.law))
      note_one_point_elements(it, spec, model, faces, *findings);
    if (findings) {
      findings->contact_interactions += (findings->contact_interactions.empty() ? "'" : ", '") + it.name + "'";
      findings->mass_scaled = model.mass_scaling.active;
    }
    interactions.push_back(s);
  }
  auto manager = std::make_unique<contact::ContactManager>(std::move(surfaces), std::move(interactions), geometry.mass,
                                                           dt, static_cast<int>(faces.global_node.size()));
  if (spec.axis) manager->set_axis(spec.axis->data(), spec.axis->data() + 3);
  manager->set_prescribed_nodes(geometry.prescribed);  // for the tangential pairs

  // Pre-flight: initial gaps and overlaps per pass, worst nodes named.
  const auto overlaps = manager->initial_overlaps(faces.coordinates.data(), 3);
  double mean_edge = 0.0;
  for (const auto& s : manager->surfaces()) mean_edge = std::max(mean_edge, s.mean_edge);
  const double tolerance = spec.initial_overlap_tolerance.value_or(0.01 * mean_edge);
  std::string worst;
  for (const auto& o : overlaps) {
    if (report)
      report->push_back(format("  initial gap %s: node %d gap %.4g m", o.pass.c_str(), faces.global_node[o.node] + 1, o.gap));
    if (-o.gap > tolerance)
      worst += format("%snode %d (%s) overlaps by %.4g m", worst.empty() ? "" : "; ", faces.global_node[o.node] + 1,
                      o.pass.c_str(), -o.gap);
  }
  if (!worst.empty())
    throw SetupError(spec.where.str() + ": error: bodies overlap at t = 0 beyond the tolerance " + format("%.3g m", tolerance) +
                     ": " + worst + "; move the bodies apart or set 'initial overlap tolerance'");
  return manager;
}

}  // namespace tribex::solver
