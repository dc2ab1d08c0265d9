// SPDX-License-Identifier: MIT
// The junction shear traction of the Junction Model (docs/theory.md 7.1): on a slave point in contact,
//   tau = -tau* phi(|v_t| / v_ref) v_t / |v_t|,   phi(s) = tanh(s),
// with v_t the relative tangential velocity of the slave point against the master surface. It
// opposes slip, has magnitude tau* once |v_t| >> v_ref (Bowden-Tabor: friction = tau* A_real), and
// is smooth at zero slip, where it acts as a damper tau = -(tau*/v_ref) v_t.
//
// Time integration (docs/theory.md 7.3). Evaluated explicitly, that damper c = tau* A_I / v_ref is stable
// only for c dt / m_eff < 2, i.e. v_ref > tau* A_I dt / (2 m_eff): about 30 m/s for tau* = 195 MPa on
// 0.4-0.8 nm silicon elements, far above sliding speeds. `junction_update` instead takes the force
// backward-Euler in the relative tangential velocity of the pair (the semi-implicit per-pair update
// of 7.3 with the full tanh law, not only its linearisation):
//   v+ = v_pred + dt F / m_eff,   F = -tau* A_I tanh(|v+| / v_ref) v+ / |v+|,
// v_pred the relative tangential velocity the next step would reach without the shear. F is
// antiparallel to v_pred, so with s = |v+| this is the scalar equation
//   s + K tanh(s / v_ref) = |v_pred|,   K = tau* A_I dt / m_eff  (the speed the full force removes in one step),
// which has one root in [0, |v_pred|] (left side increasing). Hence |F| <= tau* A_I and
// |F| <= m_eff |v_pred| / dt (never more than the stick force: the kinematic cap of 7.3 step 4 is the
// limit v_ref -> 0), v+ keeps the direction of v_pred (no overshoot, unconditionally stable), and the
// force reverses with v_pred.
#pragma once

#include <algorithm>
#include <cmath>

namespace tribex::contact {

struct JunctionLaw {
  double strength = 0.0;         // tau*, Pa
  double reference_speed = 0.1;  // v_ref, m/s
  double gap_tolerance = 0.0;    // g_j: in contact when g <= g_j (penalty contact g < 0 included), m
};

/// Shear traction (Pa, vector) for a relative tangential velocity vt (m/s), explicit evaluation.
inline void junction_traction(const double vt[3], const JunctionLaw& law, double tau[3]) {
  const double speed = std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
  const double s = speed / law.reference_speed;
  // tanh(s)/s -> 1 as s -> 0: the law is the damper -(tau*/v_ref) v_t there, no 0/0.
  const double ratio = s > 1e-8 ? std::tanh(s) / s : 1.0 - s * s / 3.0;
  const double c = law.strength / law.reference_speed * ratio;
  for (int i = 0; i < 3; ++i) tau[i] = -c * vt[i];
}

/// Speed s = |v+| after a backward-Euler step of the junction force: the root of
/// s + K tanh(s / v_ref) = v_pred in [0, v_pred] (K = capacity dt / m_eff, m/s; v_pred >= 0).
/// Newton from s = 0: the left side g(s) is increasing and concave, so the iterates rise
/// monotonically to the root (each tangent lies above g) and never leave the bracket.
/// v_ref = 0 is the unregularised limit: s = max(v_pred - K, 0) (exact stick below the capacity).
inline double junction_slip_speed(double v_pred, double K, double v_ref) {
  if (!(v_pred > 0.0)) return 0.0;
  if (!(v_ref > 0.0)) return std::max(v_pred - K, 0.0);
  double s = 0.0;
  for (int it = 0; it < 60; ++it) {
    const double th = std::tanh(s / v_ref);
    const double g = s + K * th - v_pred;
    const double dg = 1.0 + K / v_ref * (1.0 - th * th);
    const double step = -g / dg;
    s += step;
    if (std::abs(step) <= 1e-13 * v_pred) break;
  }
  return std::min(std::max(s, 0.0), v_pred);
}

/// The result of one junction update on a pair.
struct JunctionUpdate {
  double force[3] = {0.0, 0.0, 0.0};  // shear force on the slave point, N (reaction on the master point)
  double slip_speed = 0.0;             // |v+|, m/s (0: stuck)
  double power = 0.0;                  // dissipated power -F . (v_now + v+) / 2, W (see below)
};

/// Backward-Euler junction force on one pair (see the file comment).
/// `vt_now`: relative tangential velocity v^{n+1/2} (the one the positions moved with);
/// `vt_pred`: the relative tangential velocity at n+3/2 without the shear (v^{n+1/2} plus dt times the
/// other forces over the masses); `capacity` = tau* A_I (times the pass factor), N; `m_eff` the pair's
/// effective mass for a force on the slave point and its reaction on the master point, kg; `dt`, s.
/// The power pairs the force with the mean of the half-step velocities before and after it, as
/// central difference does in its energy ledger (solver/integrators/central_difference.cpp), so
/// for an isolated pair sum(power dt) equals the kinetic energy removed, to round-off.
inline JunctionUpdate junction_update(const double vt_now[3], const double vt_pred[3], double capacity, double m_eff,
                                      double dt, const JunctionLaw& law) {
  JunctionUpdate out;
  const double vp = std::sqrt(vt_pred[0] * vt_pred[0] + vt_pred[1] * vt_pred[1] + vt_pred[2] * vt_pred[2]);
  if (!(vp > 0.0) || !(capacity > 0.0)) return out;
  const double K = capacity * dt / m_eff;
  const double s = junction_slip_speed(vp, K, law.reference_speed);
  // F = m_eff (v+ - v_pred) / dt = -(m_eff (vp - s) / dt) v_pred / vp; (vp - s) = K tanh(s / v_ref).
  const double magnitude = m_eff * (vp - s) / dt;
  double power = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double e = vt_pred[i] / vp;
    out.force[i] = -magnitude * e;
    power -= out.force[i] * 0.5 * (vt_now[i] + s * e);
  }
  out.slip_speed = s;
  out.power = power;
  return out;
}

}  // namespace tribex::contact
