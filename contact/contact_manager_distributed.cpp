// SPDX-License-Identifier: MIT
// ContactManager in a distributed run (contact/README.md "Distributed contact"): which nodes this
// rank counts and holds, how far its region must reach, the per-node state a node brings into a
// region, and the totals combined over the ranks.
#include <algorithm>
#include <cmath>

#include "contact/contact_manager.hpp"
#include "contact/mortar/mortar_enforcement.hpp"

namespace tribex::contact {

void ContactManager::distribute(std::vector<char> counted, ContactReductions* reductions, const double* X) {
  counted_ = std::move(counted);
  reductions_ = reductions;
  largest_face_diameter_ = 0.0;
  for (const auto& s : surfaces_) largest_face_diameter_ = std::max(largest_face_diameter_, max_face_diameter(s, X));
  for (auto& p : passes_) p.searched = false;
  owner_computes_ = reductions != nullptr &&
                   std::none_of(passes_.begin(), passes_.end(), [](const Pass& p) { return p.mortar != nullptr; });
  const bool tangential =
      std::any_of(passes_.begin(), passes_.end(), [](const Pass& p) { return has_tangential_pairs(p.law); });
  projected_.clear();
  seeds_.clear();
  completed_.clear();
  if (owner_computes_) {
    projected_ = counted_;
    seeds_.assign(counted_.size(), 0);
    for (const auto& p : passes_)
      for (int node : surfaces_[p.slave].nodes) seeds_[node] = counted_[node];
    if (tangential) completed_.assign(4 * counted_.size(), 0.0);
    // The gaps of the slave faces around the counted nodes: the edge radius (axis) and the junction's
    // contact shares (laws/junction.cpp) read them.
    if (axis_.set || tangential)
      for (const auto& p : passes_) {
        const ContactSurface& s = surfaces_[p.slave];
        for (int f = 0; f < s.face_count(); ++f) {
          const int* fn = &s.face_nodes[4 * f];
          if (counted_[fn[0]] || counted_[fn[1]] || counted_[fn[2]] || counted_[fn[3]])
            for (int a = 0; a < 4; ++a) projected_[fn[a]] = 1;
        }
      }
  }
}

void ContactManager::set_present(const std::vector<char>& present) { present_.assign(present.begin(), present.end()); }

long long ContactManager::present_face_count() const {
  long long count = 0;
  for (const auto& s : surfaces_)
    for (int f = 0; f < s.face_count(); ++f) {
      const int* fn = &s.face_nodes[4 * f];
      count += present_.empty() || (present_[fn[0]] && present_[fn[1]] && present_[fn[2]] && present_[fn[3]]);
    }
  return count;
}

// One hop: a slave node's force reaches the nodes of the master face it projects on (within the
// capture, plus the face's extent, faces deforming up to half their size between searches), and the
// same back. A node's contact force is complete when every slave node within one hop is projected
// correctly, which needs the master faces within one more hop: two hops. A pass with tangential
// pairs reads the normal forces and master shares of its master nodes (both one hop further) and
// a later pass reads the forces of the earlier ones: two hops more per such pass. Between searches
// every node moves at most research_fraction x margin, and two nodes close by twice that, per hop.
// Owner-computes runs (every slave node computed once, the forces summed back; a tangential pass
// completes its pairs' normal forces and master shares over the ranks before it reads them) need only
// the master faces of their own slave nodes and of the slave faces around them: one hop plus a face.
double ContactManager::region_reach() const {
  double hop = 0.0;
  int hops = 2;
  for (const auto& p : passes_) {
    const double capture = p.mortar ? p.margin + 1.25 * largest_face_diameter_ : p.margin;
    hop = std::max(hop, capture + 1.5 * largest_face_diameter_ + 2.0 * p.research_fraction * p.margin);
    if (has_tangential_pairs(p.law)) hops += 2;
  }
  return owner_computes_ ? hop + 1.5 * largest_face_diameter_ : hops * hop;
}

const std::vector<char>& ContactManager::rows_read() {
  if (!owner_computes_) {
    read_.assign(present_.begin(), present_.end());
    return read_;
  }
  read_.assign(projected_.begin(), projected_.end());
  for (const auto& p : passes_) {
    const ContactSurface& slave = surfaces_[p.slave];
    const ContactSurface& master = surfaces_[p.master];
    if (p.candidate_offset.size() != static_cast<std::size_t>(slave.node_count()) + 1) continue;  // not searched
    for (int k = 0; k < slave.node_count(); ++k)
      for (int c = p.candidate_offset[k]; c < p.candidate_offset[k + 1]; ++c) {
        const int* fn = &master.face_nodes[4 * p.candidates[c]];
        for (int a = 0; a < 4; ++a) read_[fn[a]] = 1;
      }
  }
  return read_;
}

ContactManager::GhostFields ContactManager::ghost_fields() const {
  GhostFields fields{false, false};
  for (const auto& p : passes_) {
    fields.velocity = fields.velocity || reads_velocity(p.law) || has_tangential_pairs(p.law);
    fields.other_force = fields.other_force || has_tangential_pairs(p.law);
  }
  return fields;
}

int ContactManager::node_state_width() const {
  int width = 0;
  for (const auto& p : passes_) width += law_state_size(p.law);
  return width;
}

// Per pass with state: the node's rows of law_state where it is a slave node (zeros elsewhere).
void ContactManager::get_node_state(int node, double* out) const {
  for (const auto& p : passes_) {
    const int size = law_state_size(p.law);
    if (size == 0) continue;
    const auto& nodes = surfaces_[p.slave].nodes;
    const auto it = std::lower_bound(nodes.begin(), nodes.end(), node);
    const bool slave = it != nodes.end() && *it == node;
    for (int i = 0; i < size; ++i)
      out[i] = slave ? p.law_state[static_cast<std::size_t>(it - nodes.begin()) * size + i] : 0.0;
    out += size;
  }
}

void ContactManager::set_node_state(int node, const double* in) {
  for (auto& p : passes_) {
    const int size = law_state_size(p.law);
    if (size == 0) continue;
    const auto& nodes = surfaces_[p.slave].nodes;
    const auto it = std::lower_bound(nodes.begin(), nodes.end(), node);
    if (it != nodes.end() && *it == node)
      for (int i = 0; i < size; ++i) p.law_state[static_cast<std::size_t>(it - nodes.begin()) * size + i] = in[i];
    in += size;
  }
}

// The sums, maxima and minima of this step over the ranks: each rank summed only the nodes it counts.
void ContactManager::reduce_totals(ContactTotals& t, double friction[3], long long step_pairs) {
  if (!reductions_) {
    work_.busiest_pairs += double(step_pairs);
    work_.all_pairs += double(step_pairs);
    return;
  }
  double sums[] = {t.normal_force, t.compressive_force, t.adhesive_force, t.adhesion_energy, t.junction_capacity,
                   t.friction_power, t.area, double(t.nodes), t.real_area, t.asperity_contacts, t.nominal_area,
                   friction[0], friction[1], friction[2], double(step_pairs)};
  reductions_->sum(sums, static_cast<int>(std::size(sums)));
  double* s = sums;
  for (double* field : {&t.normal_force, &t.compressive_force, &t.adhesive_force, &t.adhesion_energy,
                        &t.junction_capacity, &t.friction_power, &t.area})
    *field = *s++;
  t.nodes = static_cast<int>(std::lround(*s++));
  for (double* field : {&t.real_area, &t.asperity_contacts, &t.nominal_area, &friction[0], &friction[1], &friction[2]})
    *field = *s++;
  work_.all_pairs += *s++;
  // Maxima and located maxima in one reduction (a maximum located at node 0 is the plain maximum):
  // the penetration, radius, the passes' stable steps as their negatives and the busiest rank's
  // candidate pairs, then the penetration ratio and each pass's fastest slave and master speeds with
  // their nodes.
  const std::size_t np = passes_.size(), located = 3 + np;
  double* value = located_value_.data();
  int* node = located_node_.data();
  value[0] = t.max_penetration;
  value[1] = t.radius_max;
  for (std::size_t i = 0; i < np; ++i) value[2 + i] = -passes_[i].stable_dt;
  value[2 + np] = double(step_pairs);
  std::fill(node, node + located, 0);
  value[located] = t.max_penetration_ratio;
  node[located] = t.penetration_node;
  for (std::size_t i = 0; i < np; ++i)
    for (int side = 0; side < 2; ++side) {
      value[located + 1 + 2 * i + side] = passes_[i].fastest[side];
      node[located + 1 + 2 * i + side] = passes_[i].fastest_node[side];
    }
  reductions_->max_at(value, node, static_cast<int>(located_value_.size()));
  t.max_penetration = value[0];
  t.radius_max = value[1];
  for (std::size_t i = 0; i < np; ++i) passes_[i].stable_dt = -value[2 + i];
  work_.busiest_pairs += value[2 + np];
  t.max_penetration_ratio = value[located];
  t.penetration_node = node[located];
  for (std::size_t i = 0; i < np; ++i)
    for (int side = 0; side < 2; ++side) {
      passes_[i].fastest[side] = value[located + 1 + 2 * i + side];
      passes_[i].fastest_node[side] = node[located + 1 + 2 * i + side];
    }
}

}  // namespace tribex::contact
