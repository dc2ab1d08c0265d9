// SPDX-License-Identifier: MIT
// The junction shear traction of the Junction Model (physics.md 7.1): on a slave point in contact,
//   tau = -tau* phi(|v_t| / v_ref) v_t / |v_t|,   phi(s) = tanh(s),
// with v_t the relative tangential velocity of the slave point against the master surface. It
// opposes slip, has magnitude tau* once |v_t| >> v_ref (Bowden-Tabor: friction = tau* A_real), and
// is smooth at zero slip, where it acts as a damper tau = -(tau*/v_ref) v_t (physics.md 7.3: explicit
// stability needs v_ref > tau* A_I dt / (2 m_eff)).
#pragma once

#include <cmath>

namespace tribex::contact {

struct JunctionLaw {
  double strength = 0.0;         // tau*, Pa
  double reference_speed = 0.1;  // v_ref, m/s
  double gap_tolerance = 0.0;    // g_j: in contact when g <= g_j (penalty contact g < 0 included), m
};

/// Shear traction (Pa, vector) for a relative tangential velocity vt (m/s).
inline void junction_traction(const double vt[3], const JunctionLaw& law, double tau[3]) {
  const double speed = std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
  const double s = speed / law.reference_speed;
  // tanh(s)/s -> 1 as s -> 0: the law is the damper -(tau*/v_ref) v_t there, no 0/0.
  const double ratio = s > 1e-8 ? std::tanh(s) / s : 1.0 - s * s / 3.0;
  const double c = law.strength / law.reference_speed * ratio;
  for (int i = 0; i < 3; ++i) tau[i] = -c * vt[i];
}

}  // namespace tribex::contact
