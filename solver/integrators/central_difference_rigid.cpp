// SPDX-License-Identifier: MIT
// The turning rigid bodies' step (docs/theory.md 1.6). A body keeps its momentum P and its angular momentum
// L about its centre of mass; the nodal velocity update of step n adds to them the impulse of the forces on
// its nodes, sum m_i (v_i* - v_i^{n-1/2}) and sum m_i r_i x (v_i* - v_i^{n-1/2}) (r_i = x_i^n - x_c^n;
// damping and dashpots included, as they act per node), eq. 1.6.1. The rigid velocity q = (V, omega) of the
// reference point that carries them solves A q = (P, L_ref) on its free components, the drives and held axes
// fixing the rest (eq. 1.6.2), with A at the mid-step rotation Q^{n+1/2} = R(dt omega / 2) Q^n (a few
// fixed-point passes): the implicit midpoint rule, whose torque-free spin keeps L exactly and the kinetic
// energy without drift. The body then moves to U^{n+1} = U^n + dt V, Q^{n+1} = R(dt omega) Q^n (eq. 1.6.3,
// Rodrigues' R, eq. 1.6.4), and each node gets the chord velocity of that motion,
// v_i = V + (R(dt omega) - 1) Q^n (X_i - X_ref) / dt^{n+1/2}: the positions stay rigid to round-off, where
// the tangent V + omega x r_i would stretch the body by (dt |omega|)^2 / 2 a step.
#include <algorithm>
#include <cmath>

#include "solver/integrators/central_difference.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {
namespace {

constexpr int N = RigidMotion::size;

// y = Q x, Q row-major.
inline void rotate(const double* Q, const double* x, double* y) {
  for (int i = 0; i < 3; ++i) y[i] = Q[3 * i] * x[0] + Q[3 * i + 1] * x[1] + Q[3 * i + 2] * x[2];
}

inline void cross(const double* a, const double* b, double* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

// C = A B, 3 x 3 row-major.
inline void multiply(const double* A, const double* B, double* C) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

// The body's centre of mass seen from its reference point, d = Q d0, and its inertia about the centre of
// mass, J_c = Q (J0 - M (|d0|^2 1 - d0 d0^T)) Q^T (the parallel-axis theorem), at rotation Q.
void mass_geometry(const RigidBodies& rb, std::size_t b, const double* Q, double d[3], double Jc[9]) {
  const double M = rb.mass[b];
  double d0[3], J0c[9], QJ[9], Qt[9];
  for (int i = 0; i < 3; ++i) d0[i] = rb.first_moment[3 * b + i] / M;
  const double dd = d0[0] * d0[0] + d0[1] * d0[1] + d0[2] * d0[2];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      J0c[3 * i + j] = rb.inertia[9 * b + 3 * i + j] - M * ((i == j ? dd : 0.0) - d0[i] * d0[j]);
      Qt[3 * i + j] = Q[3 * j + i];
    }
  rotate(Q, d0, d);
  multiply(Q, J0c, QJ);
  multiply(QJ, Qt, Jc);
}

// (R(dt omega) - 1) / dt = (sin a / a) [omega]x + ((1 - cos a) / a^2) dt [omega]x^2, a = dt |omega| (eq. 1.6.4
// over dt): the chord velocity's rotation part without the difference of two positions, so a short step
// (the last, shortened to land on the end) does not divide their round-off by its length.
void chord_rate(const double omega[3], double dt, double G[9]) {
  const double a2 = dt * dt * (omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2]), a = std::sqrt(a2);
  const double s = a < 1e-4 ? 1.0 - a2 / 6.0 : std::sin(a) / a;
  const double c = a < 1e-4 ? 0.5 - a2 / 24.0 : (1.0 - std::cos(a)) / a2;
  const double W[9] = {0.0, -omega[2], omega[1], omega[2], 0.0, -omega[0], -omega[1], omega[0], 0.0};
  double W2[9];
  multiply(W, W, W2);
  for (int j = 0; j < 9; ++j) G[j] = s * W[j] + c * dt * W2[j];
}

}  // namespace

// `bc` = (P, L) about the centre of mass at the step's rotation; out: q = (V, omega) of the reference point.
void CentralDifference::solve_turning_velocity(std::size_t b, bool record, const double bc[6], double q[6]) const {
  const RigidBodies& rb = model_.rigid_bodies;
  const double* now = &rigid_motion_.now[N * b];
  // The drives at this step, as apply_constraints takes them: a velocity at t^{n+1/2}, a displacement or
  // angle reached at t^{n+1}; at t = 0 (init) a velocity drive at t^0 and the others from the nodes.
  const double h = dt_half_;
  unsigned char known[6];
  double drive[6];
  for (int j = 0; j < 6; ++j) {
    const unsigned char kind = rb.drive_kind[6 * b + j];
    const double scale = rb.drive_scale[6 * b + j];
    known[j] = 1;
    drive[j] = 0.0;
    if (kind == 2) {
      drive[j] = scale * model_.functions[rb.drive_function[6 * b + j]](record ? time_ + 0.5 * h : time_);
    } else if (kind == 1 && record) {
      const double reached = j < 3 ? now[RigidMotion::U + j] : now[RigidMotion::theta + j - 3];
      drive[j] = (scale * model_.functions[rb.drive_function[6 * b + j]](time_ + h) - reached) / h;
    } else if (j < 3 || kind == 1 || rb.axis_free[3 * b + j - 3]) {
      known[j] = 0;  // a free translation or axis (or, at t = 0, a displacement or angle drive)
    }  // else a held axis: omega_j = 0
  }
  // Fixed-point passes on the mid-step rotation (at t = 0 the rotation is 1): each gains a factor dt |omega|
  // (below 1e-3 in any stable run), so four leave the solution at round-off.
  double omega[3] = {now[RigidMotion::omega], now[RigidMotion::omega + 1], now[RigidMotion::omega + 2]};
  for (int pass = 0; pass < (record ? 4 : 1); ++pass) {
    double half[3], R[9], Qm[9], d[3], Jc[9], S[3], J[9], bref[6], dP[3];
    for (int i = 0; i < 3; ++i) half[i] = 0.5 * h * (record ? omega[i] : 0.0);
    rotation_matrix(half, R);
    multiply(R, &now[RigidMotion::Q], Qm);
    mass_geometry(rb, b, Qm, d, Jc);
    // About the reference point: S = M d, J = J_c + M (|d|^2 1 - d d^T), L_ref = L_c + d x P.
    const double M = rb.mass[b], dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    cross(d, bc, dP);
    for (int i = 0; i < 3; ++i) {
      S[i] = M * d[i];
      bref[i] = bc[i];
      bref[3 + i] = bc[3 + i] + dP[i];
      for (int j = 0; j < 3; ++j) J[3 * i + j] = Jc[3 * i + j] + M * ((i == j ? dd : 0.0) - d[i] * d[j]);
    }
    for (int j = 0; j < 6; ++j) q[j] = drive[j];
    solve_rigid_velocity(M, S, J, bref, known, q);
    for (int i = 0; i < 3; ++i) omega[i] = q[3 + i];
  }
}

// The body's (P, L) at n+1/2 from q: P = M (V + omega x d), L = J_c omega, at the mid-step rotation.
static void store_momentum(const RigidBodies& rb, std::size_t b, const double* Qn, double h, const double q[6],
                           double* next) {
  double half[3], R[9], Qm[9], d[3], Jc[9], wd[3];
  for (int i = 0; i < 3; ++i) half[i] = 0.5 * h * q[3 + i];
  rotation_matrix(half, R);
  multiply(R, Qn, Qm);
  mass_geometry(rb, b, Qm, d, Jc);
  cross(q + 3, d, wd);
  rotate(Jc, q + 3, next + RigidMotion::L);
  for (int i = 0; i < 3; ++i) next[RigidMotion::P + i] = rb.mass[b] * (q[i] + wd[i]);
}

// The body at t^{n+1}: U, theta, Q advanced by dt^{n+1/2} with q, and omega at t^n for the history.
static void advance_motion(const double* now, double h, const double q[6], bool first_step, double* next, double* omega_n) {
  double turn[3], R[9];
  for (int i = 0; i < 3; ++i) {
    next[RigidMotion::U + i] = now[RigidMotion::U + i] + h * q[i];
    next[RigidMotion::theta + i] = now[RigidMotion::theta + i] + h * q[3 + i];
    next[RigidMotion::omega + i] = q[3 + i];
    omega_n[i] = first_step ? now[RigidMotion::omega + i] : 0.5 * (now[RigidMotion::omega + i] + q[3 + i]);
    turn[i] = h * q[3 + i];
  }
  rotation_matrix(turn, R);
  multiply(R, now + RigidMotion::Q, next + RigidMotion::Q);
}

void CentralDifference::move_turning_bodies(bool record) {
  const RigidBodies& rb = model_.rigid_bodies;
  RigidMotion& m = rigid_motion_;
  if (record) m.now = m.next;  // the body at time n
  // The impulse of this step's nodal update about the centre of mass at t^n (at t = 0: the nodes' momentum).
  std::fill(rigid_turning_sums_.begin(), rigid_turning_sums_.end(), 0.0);
  for (std::size_t b = 0; b < rb.size(); ++b) {
    if (!rb.rotating[b]) continue;
    const double* Q = &m.now[N * b + RigidMotion::Q];
    double d0[3];
    for (int i = 0; i < 3; ++i) d0[i] = rb.first_moment[3 * b + i] / rb.mass[b];
    double* s = &rigid_turning_sums_[6 * b];
    for (int k = rb.first[b]; k < rb.first[b + 1]; ++k) {
      const auto n = static_cast<std::size_t>(rb.node[k]);
      const double w = rb.owned[k] * model_.mass[n];
      double a[3], r[3], dv[3], rv[3];
      for (int i = 0; i < 3; ++i) {
        a[i] = rb.arm[3 * static_cast<std::size_t>(k) + i] - d0[i];
        dv[i] = v_[3 * n + i] - (record ? v_prev_[3 * n + i] : 0.0);
      }
      rotate(Q, a, r);
      cross(r, dv, rv);
      for (int i = 0; i < 3; ++i) {
        s[i] += w * dv[i];
        s[3 + i] += w * rv[i];
      }
    }
  }
  if (!model_.domain.serial()) parallel::sum(rigid_turning_sums_.data(), static_cast<int>(rigid_turning_sums_.size()));
  const double h = dt_half_, inverse_dt = record && dt_n_ > 0.0 ? 1.0 / dt_n_ : 0.0;
  for (std::size_t b = 0; b < rb.size(); ++b) {
    if (!rb.rotating[b]) continue;
    double* now = &m.now[N * b];
    double* next = &m.next[N * b];
    double bc[6], q[6];
    for (int j = 0; j < 6; ++j) bc[j] = rigid_turning_sums_[6 * b + j] + (record ? now[RigidMotion::P + j] : 0.0);
    solve_turning_velocity(b, record, bc, q);
    if (record) {
      advance_motion(now, h, q, step_ == 0, next, &m.omega_n[3 * b]);
      store_momentum(rb, b, now + RigidMotion::Q, h, q, next);
    } else {  // t = 0: omega^{-1/2} = omega^0, the nodes' own rigid velocity
      for (int i = 0; i < 3; ++i) now[RigidMotion::omega + i] = next[RigidMotion::omega + i] = m.omega_n[3 * b + i] = q[3 + i];
      store_momentum(rb, b, now + RigidMotion::Q, 0.0, q, next);
      std::copy(next + RigidMotion::P, next + N, now + RigidMotion::P);
    }
    // record: the chord V + (R - 1) r_i^n / dt (chord_rate); t = 0: V + omega x r_i (Q = 1).
    double G[9], GQ[9];
    if (record) {
      chord_rate(q + 3, h, G);
      multiply(G, now + RigidMotion::Q, GQ);
    } else {
      const double W[9] = {0.0, -q[5], q[4], q[5], 0.0, -q[3], -q[4], q[3], 0.0};
      std::copy(W, W + 9, GQ);
    }
    for (int k = rb.first[b]; k < rb.first[b + 1]; ++k) {
      const auto n = static_cast<std::size_t>(rb.node[k]);
      double turn[3];
      rotate(GQ, &rb.arm[3 * static_cast<std::size_t>(k)], turn);
      for (int i = 0; i < 3; ++i) {
        double& v = v_[3 * n + i];
        const double v_new = q[i] + turn[i];
        rigid_coupling_[3 * static_cast<std::size_t>(k) + i] = model_.mass[n] * (v_new - v) * inverse_dt;
        v = v_new;
      }
    }
  }
}

// W += (1/2) g . (v^{n-1/2} + v^{n+1/2}) dt in the pairing of sum_load_power: a driven body's coupling forces
// are its drives' reactions (plus the rigidity's share, which does no work, docs/theory.md 1.6).
void CentralDifference::sum_rigid_drive_power(StepSums& s) const {
  const RigidBodies& rb = model_.rigid_bodies;
  for (std::size_t b = 0; b < rb.size(); ++b) {
    if (!rb.rotating[b] || !rb.driven(b)) continue;
    for (int k = rb.first[b]; k < rb.first[b + 1]; ++k) {
      const auto n = static_cast<std::size_t>(rb.node[k]);
      const double* g = &rigid_coupling_[3 * static_cast<std::size_t>(k)];
      for (int i = 0; i < 3; ++i) {
        s.external_left += rb.owned[k] * g[i] * v_prev_[3 * n + i];
        s.external_right += rb.owned[k] * g[i] * v_[3 * n + i];
      }
    }
  }
}

}  // namespace tribex::solver
