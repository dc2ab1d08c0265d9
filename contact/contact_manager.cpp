// SPDX-License-Identifier: MIT
#include "contact/contact_manager.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "contact/geometry/axis_distance.hpp"
#include "contact/node_to_face/closest_face.hpp"

namespace tribex::contact {

ContactManager::ContactManager(std::vector<ContactSurface> surfaces, std::vector<InteractionSettings> interactions,
                               const std::vector<double>& mass, double dt_ref, int node_count)
    : surfaces_(std::move(surfaces)), mass_(mass), dt_ref_(dt_ref) {
  for (const auto& it : interactions) {
    const int order[2][2] = {{it.slave, it.master}, {it.master, it.slave}};
    for (int k = 0; k < (it.symmetric ? 2 : 1); ++k) {
      Pass p;
      p.slave = order[k][0];
      p.master = order[k][1];
      p.factor = it.symmetric ? 0.5 : 1.0;
      p.margin = it.search_margin > 0 ? it.search_margin : surfaces_[p.master].mean_edge;
      p.research_fraction = it.research_fraction;
      p.penalty_scale = it.penalty_scale;
      p.force_along_axis = it.force_along_axis;
      p.law = it.law;
      p.primary = k == 0;
      p.x_at_search.resize(3 * (surfaces_[p.slave].nodes.size() + surfaces_[p.master].nodes.size()));
      const std::size_t n = surfaces_[p.slave].nodes.size();
      if (has_tangential_pairs(p.law)) p.pairs.size_for(n);
      p.law_state.assign(n * static_cast<std::size_t>(law_state_size(p.law)), 0.0);
      p.face_bounds.resize(surfaces_[p.master].face_count());
      p.nearest_face.assign(n, -1);
      if (it.enforcement == Enforcement::mortar) {
        if (!supports_mortar(it.law))
          throw std::invalid_argument("contact interaction '" + it.name + "': " +
                                      mortar_problem(law_index(law_name(it.law))));
        p.mortar = std::make_unique<MortarEnforcement>(surfaces_[p.slave]);
        p.penalty_per_area = mortar_penalty_per_area(surfaces_[p.slave], surfaces_[p.master], mass, p.penalty_scale, dt_ref);
      }
      passes_.push_back(std::move(p));
    }
  }
  traction_.assign(3 * static_cast<std::size_t>(node_count), 0.0);
  master_share_.assign(static_cast<std::size_t>(node_count), 0.0);
  status_.assign(static_cast<std::size_t>(node_count), 0.0);
  std::size_t primary_slave_nodes = 0;
  for (const auto& p : passes_)
    if (p.primary) primary_slave_nodes += surfaces_[p.slave].nodes.size();
  fit_r2_.reserve(primary_slave_nodes);
  fit_p2_.reserve(primary_slave_nodes);
  plan_.assign(passes_.size(), 0.0);
  located_value_.assign(4 + 3 * passes_.size(), 0.0);
  located_node_.assign(4 + 3 * passes_.size(), -1);
  for (const auto& s : surfaces_) all_nodes_.insert(all_nodes_.end(), s.nodes.begin(), s.nodes.end());
  std::sort(all_nodes_.begin(), all_nodes_.end());
  all_nodes_.erase(std::unique(all_nodes_.begin(), all_nodes_.end()), all_nodes_.end());
}

void ContactManager::set_unscaled_penalty_reference(std::vector<double> unscaled_mass, double unscaled_dt) {
  penalty_mass_ = std::move(unscaled_mass);
  penalty_dt_ = unscaled_dt;
  for (auto& p : passes_)
    if (p.mortar)
      p.penalty_per_area =
          std::min(mortar_penalty_per_area(surfaces_[p.slave], surfaces_[p.master], penalty_mass_, p.penalty_scale,
                                           penalty_dt_),
                   mortar_penalty_per_area(surfaces_[p.slave], surfaces_[p.master], mass_, p.penalty_scale, dt_ref_));
}

double ContactManager::penalty_stiffness(double scale, const ContactPoint& point) const {
  const double k = scale * effective_mass(mass_, point) / (dt_ref_ * dt_ref_);
  if (penalty_mass_.empty()) return k;
  const double unscaled = scale * effective_mass(penalty_mass_, point) / (penalty_dt_ * penalty_dt_);
  return std::min(unscaled, k);
}

void ContactManager::set_axis(const double point[3], const double direction[3]) {
  const double n = std::sqrt(direction[0] * direction[0] + direction[1] * direction[1] + direction[2] * direction[2]);
  for (int i = 0; i < 3; ++i) {
    axis_.point[i] = point[i];
    axis_.direction[i] = direction[i] / n;
  }
  axis_.set = true;
}

// The largest squared motion of the pass's counted nodes since its last search, m^2 (both surfaces
// move: a pair can close by twice the largest node motion).
double ContactManager::motion_since_search(const Pass& p, const double* x) const {
  double largest = 0.0;
  std::size_t k = 0;
  for (int s : {p.slave, p.master})
    for (int node : surfaces_[s].nodes) {
      if (counts(node)) {
        double d2 = 0.0;
        for (int i = 0; i < 3; ++i) {
          const double d = x[3 * node + i] - p.x_at_search[3 * k + i];
          d2 += d * d;
        }
        largest = std::max(largest, d2);
      }
      ++k;
    }
  return largest;
}

bool ContactManager::plan_searches(const double* x) {
  for (std::size_t i = 0; i < passes_.size(); ++i)
    plan_[i] = passes_[i].searched ? motion_since_search(passes_[i], x) : INFINITY;
  if (reductions_) reductions_->max(plan_.data(), static_cast<int>(plan_.size()));
  bool any = false;
  for (std::size_t i = 0; i < passes_.size(); ++i) {
    const double limit = passes_[i].research_fraction * passes_[i].margin;
    passes_[i].search_due = plan_[i] > limit * limit;
    any = any || passes_[i].search_due;
  }
  // A distributed run refreshes its region when any pass searches: every pass then searches the new one.
  if (any && reductions_)
    for (auto& p : passes_) p.search_due = 1;
  return any;
}

// One-step motion of the pass's surfaces against its capture distance (ContactTotals::motion_ratio). It
// bounds the relative approach from the nodes' speeds alone, so it also sees a body that is still far
// from the other one and would pass through it within the step (tunnelling).
void ContactManager::track_motion(Pass& p, const double* v) const {
  for (int side = 0; side < 2; ++side) {
    p.fastest[side] = 0.0;
    p.fastest_node[side] = -1;
    for (int node : surfaces_[side == 0 ? p.slave : p.master].nodes) {
      if (!counts(node)) continue;
      const double* vn = v + 3 * node;
      const double s2 = vn[0] * vn[0] + vn[1] * vn[1] + vn[2] * vn[2];
      if (s2 > p.fastest[side]) {
        p.fastest[side] = s2;
        p.fastest_node[side] = node;
      }
    }
  }
}

void ContactManager::search(Pass& p, const double* x) {
  const char* present = present_.empty() ? nullptr : present_.data();
  if (p.mortar && p.capture == 0.0) {
    double diameter = max_face_diameter(surfaces_[p.slave], x, present);
    if (reductions_) reductions_->max(&diameter, 1);
    p.capture = p.margin + 1.25 * diameter;
  }
  bucket_.find_candidates(x, surfaces_[p.slave], surfaces_[p.master], p.mortar ? p.capture : p.margin,
                          p.candidate_offset, p.candidates, present, owner_computes_ ? projected_.data() : nullptr);
  if (p.mortar) {
    // Headroom for later searches (the wide mortar capture gives more candidates): no allocation in the loop.
    if (p.candidates.capacity() < p.candidates.size() + p.candidates.size() / 4)
      p.candidates.reserve(p.candidates.size() + p.candidates.size() / 2);
    p.mortar->reserve(surfaces_[p.slave], p.candidate_offset);
  }
  p.last_face.assign(surfaces_[p.slave].nodes.size(), -1);
  std::size_t k = 0;
  for (int s : {p.slave, p.master})
    for (int node : surfaces_[s].nodes) {
      for (int i = 0; i < 3; ++i) p.x_at_search[3 * k + i] = x[3 * node + i];
      ++k;
    }
  p.searched = true;
  ++total_searches_;
  ++work_.searches;
}

double ContactManager::stable_time_step() const {
  double dt = INFINITY;
  for (const auto& p : passes_) dt = std::min(dt, p.stable_dt);
  return dt;
}

ContactTotals ContactManager::compute_forces(const double* x, const double* v, double* force, const double* other_force,
                                             double dt) {
  if (!(dt > 0.0)) dt = dt_ref_;
  ContactTotals totals;
  ++work_.calls;
  double friction[3] = {0.0, 0.0, 0.0};  // vector sum of shear forces on the (first) slave surfaces, N
  fit_r2_.clear();
  fit_p2_.clear();
  uncounted_ = UncountedTotals{};  // scratch: what other ranks report
  for (int node : all_nodes_) {
    status_[node] = 0.0;
    traction_[3 * node] = traction_[3 * node + 1] = traction_[3 * node + 2] = 0.0;
  }
  if (std::any_of(passes_.begin(), passes_.end(), [](const Pass& p) { return p.search_due < 0; })) plan_searches(x);
  long long step_pairs = 0;  // candidate pairs of this evaluation, all passes
  for (auto& p : passes_) {
    if (p.search_due) {
      search(p, x);
      ++totals.searches;
    } else {
      ++work_.reuses;
    }
    p.search_due = -1;
    if (!p.candidate_offset.empty()) step_pairs += p.candidate_offset.back();
    p.gap.assign(surfaces_[p.slave].nodes.size(), NAN);
    p.stable_dt = INFINITY;
    if (v) track_motion(p, v);
    if (p.mortar)
      apply_mortar(p, x, force, totals);
    else
      node_to_face(p, {x, v, other_force, dt, force}, totals, friction);
    if (axis_.set && p.primary) totals.radius_edge = edge_radius(p, x);
  }
  work_.pairs += step_pairs;
  reduce_totals(totals, friction, step_pairs);
  if (v)
    for (const auto& p : passes_) {
      const double capture = p.mortar && p.capture > 0.0 ? p.capture : p.margin;
      const double ratio = dt * (std::sqrt(p.fastest[0]) + std::sqrt(p.fastest[1])) / capture;
      if (ratio > totals.motion_ratio) {
        totals.motion_ratio = ratio;
        totals.motion_node = p.fastest[0] >= p.fastest[1] ? p.fastest_node[0] : p.fastest_node[1];
      }
    }
  if (axis_.set) totals.radius_pressure_fit = pressure_fit_radius();
  totals.normal_force = totals.compressive_force - totals.adhesive_force;
  totals.tangential_force = std::sqrt(friction[0] * friction[0] + friction[1] * friction[1] + friction[2] * friction[2]);
  return totals;
}

std::vector<ContactManager::Overlap> ContactManager::initial_overlaps(const double* x, int worst_count) {
  std::vector<Overlap> out;
  for (auto& p : passes_) {
    search(p, x);
    const ContactSurface& slave = surfaces_[p.slave];
    const ContactSurface& master = surfaces_[p.master];
    std::vector<Overlap> pass;
    for (int k = 0; k < slave.node_count(); ++k) {
      const int count = p.candidate_offset[k + 1] - p.candidate_offset[k];
      if (count == 0) continue;
      const BestFace best = closest_face(x, master, &p.candidates[p.candidate_offset[k]], count, x + 3 * slave.nodes[k]);
      if (best.usable)
        pass.push_back({slave.name + " -> " + master.name, slave.nodes[k], best.proj.gap});
    }
    std::sort(pass.begin(), pass.end(), [](const Overlap& a, const Overlap& b) { return a.gap < b.gap; });
    if (pass.size() > static_cast<std::size_t>(worst_count)) pass.resize(static_cast<std::size_t>(worst_count));
    out.insert(out.end(), pass.begin(), pass.end());
  }
  return out;
}

}  // namespace tribex::contact
