// SPDX-License-Identifier: MIT
#include "contact/node_to_face/tangential_pairs.hpp"

#include "contact/geometry/axis_distance.hpp"

namespace tribex::contact {

void TangentialPairs::size_for(std::size_t n) {
  slave.resize(n);
  face.resize(n);
  shape.resize(4 * n);
  normal.resize(3 * n);
  normal_force.resize(n);
  vt.resize(3 * n);
  vpred.resize(3 * n);
  share.resize(n);
}

void TangentialPairs::record(const ContactPoint& p) {
  const int j = count++;
  slave[j] = p.k;
  face[j] = p.face;
  for (int a = 0; a < 4; ++a) shape[4 * j + a] = p.shape[a];
  for (int i = 0; i < 3; ++i) normal[3 * j + i] = p.normal[i];
  normal_force[j] = p.normal_force;
}

void PassView::count_contact(const ContactPoint& p, bool count_area) const {
  status[p.node] = 1.0;
  ContactTotals& t = totals_of(p.node);
  if (count_area) t.area += factor * p.area;
  if (primary) ++t.nodes;
  if (axis.set) t.radius_max = std::max(t.radius_max, axis_distance(x + 3 * p.node, axis.point, axis.direction));
}

namespace {

// Owner computes: this rank's parts of the contact forces and master shares, summed over the ranks
// into the view's scratch rows [node][4] (every rank calls this in every tangential pass: it communicates).
void complete_over_ranks(PassView& view) {
  const std::size_t n = view.mass.size();
  double* rows = view.completed;
  for (std::size_t k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i) rows[4 * k + i] = view.force[3 * k + i];
    rows[4 * k + 3] = view.master_share[k];
  }
  view.completion->complete_node_sums(rows, 4);
}

// What the prediction and the pair mass read: the completed rows where other ranks' pairs add to them.
double force_of(const PassView& view, int node, int i) {
  return view.completion ? view.completed[4 * node + i] : view.force[3 * node + i];
}
double share_of(const PassView& view, int node) {
  return view.completion ? view.completed[4 * node + 3] : view.master_share[node];
}

}  // namespace

void predict_pair_velocities(PassView& view) {
  TangentialPairs& q = view.pairs;
  const int* master_nodes = view.master.face_nodes.data();
  for (int j = 0; j < q.count; ++j) {
    const int* fn = master_nodes + 4 * q.face[j];
    for (int a = 0; a < 4; ++a) view.master_share[fn[a]] += q.shape[4 * j + a];
  }
  if (view.completion) complete_over_ranks(view);
  auto predicted = [&](int node, int i) {
    const double f = force_of(view, node, i) + (view.other_force ? view.other_force[3 * node + i] : 0.0);
    return view.is_prescribed(node) ? view.v[3 * node + i] : view.v[3 * node + i] + view.dt * f / view.mass[node];
  };
  // Trial velocities of all pairs first (Jacobi: the forces of one pair do not enter another's trial).
  for (int j = 0; j < q.count; ++j) {
    const int node = view.slave.nodes[q.slave[j]];
    const int* fn = master_nodes + 4 * q.face[j];
    const double* N = &q.shape[4 * j];
    const double* n = &q.normal[3 * j];
    double vr[3], vp[3];
    for (int i = 0; i < 3; ++i) {
      vr[i] = view.v[3 * node + i];
      vp[i] = predicted(node, i);
      for (int a = 0; a < 4; ++a) {
        vr[i] -= N[a] * view.v[3 * fn[a] + i];
        vp[i] -= N[a] * predicted(fn[a], i);
      }
    }
    const double vrn = vr[0] * n[0] + vr[1] * n[1] + vr[2] * n[2];
    const double vpn = vp[0] * n[0] + vp[1] * n[1] + vp[2] * n[2];
    for (int i = 0; i < 3; ++i) {
      q.vt[3 * j + i] = vr[i] - vrn * n[i];
      q.vpred[3 * j + i] = vp[i] - vpn * n[i];
    }
  }
}

double pair_mass(const PassView& view, int j) {
  const TangentialPairs& q = view.pairs;
  const int node = view.slave.nodes[q.slave[j]];
  const int* fn = &view.master.face_nodes[4 * q.face[j]];
  const double* N = &q.shape[4 * j];
  // A node whose velocity is prescribed takes no share (its mass is infinite for the pair).
  double inv_m = view.is_prescribed(node) ? 0.0 : 1.0 / view.mass[node];
  for (int a = 0; a < 4; ++a)
    if (!view.is_prescribed(fn[a])) inv_m += N[a] * share_of(view, fn[a]) / view.mass[fn[a]];
  // A symmetric interaction updates the pair in both passes, each with half the capacity and
  // half the stick force (pair mass times the pass factor). Both sides prescribed: no update (0).
  return inv_m > 0.0 ? view.factor / inv_m : 0.0;
}

void apply_pair_update(PassView& view, int j, const JunctionUpdate& up) {
  const TangentialPairs& q = view.pairs;
  const int k = q.slave[j];
  const int node = view.slave.nodes[k];
  const int* fn = &view.master.face_nodes[4 * q.face[j]];
  const double* N = &q.shape[4 * j];
  const double sign = view.primary ? 1.0 : -1.0;
  for (int i = 0; i < 3; ++i) {
    view.force[3 * node + i] += up.force[i];
    for (int a = 0; a < 4; ++a) view.force[3 * fn[a] + i] -= N[a] * up.force[i];
    view.traction[3 * node + i] += up.force[i] / view.slave.node_area[k];
    view.friction_of(node)[i] += sign * up.force[i];
  }
  view.totals_of(node).friction_power += up.power;
}

void end_pairs(PassView& view) {
  TangentialPairs& q = view.pairs;
  for (int j = 0; j < q.count; ++j) {
    const int* fn = &view.master.face_nodes[4 * q.face[j]];
    for (int a = 0; a < 4; ++a) view.master_share[fn[a]] = 0.0;
  }
  q.count = 0;
}

}  // namespace tribex::contact
