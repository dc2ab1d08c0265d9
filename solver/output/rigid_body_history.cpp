// SPDX-License-Identifier: MIT
#include "solver/output/rigid_body_history.hpp"

#include <algorithm>

#include "solver/model.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {

std::vector<ColumnInfo> describe_rigid_body_columns(const RigidBodies& rb) {
  std::vector<ColumnInfo> out;
  for (std::size_t k = 0; k < rb.size(); ++k)
    for (auto& c : describe_rigid_body_columns({rb.name[k]}, rb.rotating[k] != 0)) out.push_back(std::move(c));
  return out;
}

std::vector<ColumnInfo> describe_rigid_body_columns(const std::vector<std::string>& bodies, bool turning) {
  std::vector<ColumnInfo> out;
  for (const std::string& b : bodies) {
    for (const char* i : {"x", "y", "z"})
      out.push_back({b + "_reaction_" + i, "N",
                     "force the reference point of rigid body '" + b + "' applies to it (prescribed force or "
                     "constraint reaction), " + i});
    for (const char* i : {"x", "y", "z"})
      out.push_back({b + "_displacement_" + i, "m", "displacement of rigid body '" + b + "' (its reference point), " + i});
    for (const char* i : {"x", "y", "z"})
      out.push_back({b + "_moment_" + i, "N m",
                     "moment of the coupling forces about the reference point of rigid body '" + b +
                     "' (" + (turning ? "what drives its rotation or holds its held axes" : "what holds its rotation fixed") +
                         "), " + i});
    if (!turning) continue;
    for (const char* i : {"x", "y", "z"})
      out.push_back({b + "_rotation_" + i, "rad",
                     "rotation vector (axis times angle) of rigid body '" + b + "' since t = 0 (a turning body), " + i});
    for (const char* i : {"x", "y", "z"})
      out.push_back({b + "_angular_velocity_" + i, "rad/s", "angular velocity of rigid body '" + b + "' (a turning body), " + i});
  }
  return out;
}

namespace {

// A turning body's values at `v`: the reaction and its moment with the current arms Q (X_i - X_ref),
// the reference point's displacement, the rotation vector and the angular velocity (this rank's part of
// the sums over nodes; the motion's columns on rank 0 only, as the sum over the ranks adds them).
void turning_body_values(const Model& model, const RigidBodyState& s, std::size_t b, const double share[3],
                         double* v) {
  const RigidBodies& rb = model.rigid_bodies;
  const double* m = &s.motion->now[RigidMotion::size * b];
  const double* Q = m + RigidMotion::Q;
  for (int k = rb.first[b]; k < rb.first[b + 1]; ++k) {
    if (!(rb.owned[k] > 0.0)) continue;
    const double* a = &rb.arm[3 * static_cast<std::size_t>(k)];
    double c[3], r[3];
    for (int i = 0; i < 3; ++i) {
      c[i] = s.coupling[3 * static_cast<std::size_t>(k) + i] + share[i];
      r[i] = Q[3 * i] * a[0] + Q[3 * i + 1] * a[1] + Q[3 * i + 2] * a[2];
      v[i] += c[i];
    }
    v[6] += r[1] * c[2] - r[2] * c[1];
    v[7] += r[2] * c[0] - r[0] * c[2];
    v[8] += r[0] * c[1] - r[1] * c[0];
  }
  if (parallel::rank() != 0) return;
  rotation_vector(Q, v + 9);
  for (int i = 0; i < 3; ++i) {
    v[3 + i] = m[RigidMotion::U + i];
    v[12 + i] = s.motion->omega_n[3 * b + i];
  }
}

}  // namespace

void rigid_body_history_values(const Model& model, const RigidBodyState& s, std::vector<double>& values) {
  const RigidBodies& rb = model.rigid_bodies;
  std::fill(values.begin(), values.end(), 0.0);
  if (rb.empty()) return;
  const double* X = model.mesh.coordinates.data();
  std::size_t offset = 0;
  for (std::size_t b = 0; b < rb.size(); offset += rb.rotating[b] ? 15 : 9, ++b) {
    double share[3] = {0.0, 0.0, 0.0};  // per node, of the prescribed forces on the body
    for (std::size_t l = 0; l < rb.load_body.size(); ++l)
      if (rb.load_body[l] == static_cast<int>(b)) {
        const NodalForceLoad& load = model.nodal_forces[rb.load_index[l]];
        share[rb.load_component[l]] += load.scale * model.functions[load.function](s.time);
      }
    double* v = &values[offset];
    if (rb.rotating[b]) {
      turning_body_values(model, s, b, share, v);
      continue;
    }
    for (int k = rb.first[b]; k < rb.first[b + 1]; ++k) {
      if (!(rb.owned[k] > 0.0)) continue;
      const std::size_t n = static_cast<std::size_t>(rb.node[k]);
      double c[3], r[3];
      for (int i = 0; i < 3; ++i) {
        c[i] = s.coupling[3 * static_cast<std::size_t>(k) + i] + s.reaction[3 * n + i] + share[i];
        // x_i - x_ref: the body translates, so the reference configuration's arm is the current one.
        r[i] = X[3 * n + i] - rb.reference[3 * b + i];
        v[i] += c[i];
        v[3 + i] += s.displacement[3 * n + i];
      }
      v[6] += r[1] * c[2] - r[2] * c[1];
      v[7] += r[2] * c[0] - r[0] * c[2];
      v[8] += r[0] * c[1] - r[1] * c[0];
    }
  }
  if (!model.domain.serial()) parallel::sum(values.data(), static_cast<int>(values.size()));
  offset = 0;
  for (std::size_t b = 0; b < rb.size(); offset += rb.rotating[b] ? 15 : 9, ++b)
    for (int i = 0; i < 3 && !rb.rotating[b]; ++i) values[offset + 3 + i] /= rb.node_count[b];
}

}  // namespace tribex::solver
