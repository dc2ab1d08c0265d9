// SPDX-License-Identifier: MIT
#include "solver/setup/rigid_bodies.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "inputs/did_you_mean.hpp"
#include "solver/errors.hpp"
#include "solver/model.hpp"
#include "solver/output/run_log.hpp"
#include "solver/parallel/communicator.hpp"

namespace tribex::solver {
namespace {

std::vector<std::string> names_of(const std::map<std::string, std::vector<int>>& sets) {
  std::vector<std::string> names;
  for (const auto& [name, nodes] : sets) names.push_back(name);
  return names;
}

[[noreturn]] void unknown(const inputs::RigidBodySpec& b, const char* what, const std::string& name,
                          const std::vector<std::string>& known) {
  const std::string hint = inputs::closest_match(name, known);
  throw SetupError(b.where.str() + ": error: rigid body '" + b.name + "': " + what + " '" + name + "' is not in the mesh" +
                   (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
}

// The nodes of a body as the deck names them: a node set, or every node of a block (sorted, unique).
std::vector<int> body_nodes(const mesh::Mesh& mesh, const inputs::RigidBodySpec& b) {
  if (!b.node_set.empty()) {
    const auto it = mesh.node_sets.find(b.node_set);
    if (it == mesh.node_sets.end()) unknown(b, "node set", b.node_set, names_of(mesh.node_sets));
    return it->second;
  }
  const mesh::Block* block = mesh.find_block(b.block);
  if (!block) {
    std::vector<std::string> blocks;
    for (const auto& k : mesh.blocks) blocks.push_back(k.name);
    unknown(b, "block", b.block, blocks);
  }
  std::vector<int> nodes;
  for (int e = block->first_element; e < block->first_element + block->element_count; ++e)
    for (int I = 0; I < 8; ++I) nodes.push_back(mesh.connectivity[8 * static_cast<std::size_t>(e) + I]);
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

int function_of(const Model& model, const std::string& name) {
  const auto it = std::find(model.function_names.begin(), model.function_names.end(), name);
  return static_cast<int>(it - model.function_names.begin());  // existence checked by the parser
}

// A turning body's drives, [6] per body: the `rigid body = NAME` motions (translation) and the prescribed
// rotations and angular velocities; a turning body is one whose rotation is free or driven.
void add_drives(const inputs::RegionSpec& region, const Model& model, RigidBodies& rb) {
  const std::size_t bodies = rb.size();
  rb.rotating.assign(bodies, 0);
  rb.axis_free.assign(3 * bodies, 0);
  rb.drive_kind.assign(6 * bodies, 0);
  rb.drive_function.assign(6 * bodies, -1);
  rb.drive_scale.assign(6 * bodies, 0.0);
  for (std::size_t b = 0; b < bodies; ++b) {
    const auto& spec = region.rigid_bodies[b];
    for (int i = 0; i < 3; ++i) rb.axis_free[3 * b + i] = spec.rotation_free && spec.free_axes[i];
    rb.rotating[b] = spec.rotation_free;
  }
  auto body_of = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(rb.name.begin(), rb.name.end(), name) - rb.name.begin());
  };
  for (const auto& p : region.prescribed_rotations) {
    const std::size_t b = body_of(p.rigid_body);
    const std::size_t j = 6 * b + 3 + static_cast<std::size_t>(p.component);
    rb.rotating[b] = 1;
    rb.drive_kind[j] = p.kind == inputs::PrescribedRotationSpec::Kind::angle ? 1 : 2;
    rb.drive_function[j] = function_of(model, p.function);
    rb.drive_scale[j] = p.scale_factor;
  }
  for (const auto& p : region.prescribed_motions) {
    if (p.rigid_body.empty()) continue;
    const std::size_t b = body_of(p.rigid_body);
    if (!rb.rotating[b]) continue;  // the translation-only step: the constraints drive every node
    const std::size_t j = 6 * b + static_cast<std::size_t>(p.component);
    rb.drive_kind[j] = p.kind == inputs::PrescribedMotionSpec::Kind::displacement ? 1 : 2;
    rb.drive_function[j] = function_of(model, p.function);
    rb.drive_scale[j] = p.scale_factor;
  }
}

// A turning body's arms, first moment and inertia about its reference point (summed over the ranks), and its
// nodes out of Model::constraints: its drives set their velocities (SetupError where a node-set condition
// constrains one; `constrained` counts the constrained nodes of each body's components, over the ranks).
void add_rotation(const inputs::RegionSpec& region, Model& model, const std::vector<double>& constrained,
                  RigidBodies& rb) {
  const std::size_t bodies = rb.size();
  rb.arm.assign(3 * rb.node.size(), 0.0);
  rb.first_moment.assign(3 * bodies, 0.0);
  rb.inertia.assign(9 * bodies, 0.0);
  if (!rb.any_rotating()) return;
  std::vector<char> turning(model.mass.size(), 0);
  for (std::size_t b = 0; b < bodies; ++b) {
    if (!rb.rotating[b]) continue;
    const auto& spec = region.rigid_bodies[b];
    for (int i = 0; i < 3; ++i)
      if (static_cast<int>(constrained[3 * b + i] + 0.5) != (rb.drive_kind[6 * b + i] ? rb.node_count[b] : 0))
        throw SetupError(spec.where.str() + ": error: rigid body '" + spec.name + "' turns (its rotation is free or " +
                         "driven), but a node-set boundary condition constrains component " + "xyz"[i] +
                         " of its nodes; drive the body instead ('rigid body = " + spec.name + "' in the condition)");
    for (int k = rb.first[b]; k < rb.first[b + 1]; ++k) {
      const auto n = static_cast<std::size_t>(rb.node[k]);
      turning[n] = 1;
      double* r = &rb.arm[3 * static_cast<std::size_t>(k)];
      for (int i = 0; i < 3; ++i) r[i] = model.mesh.coordinates[3 * n + i] - rb.reference[3 * b + i];
      const double w = rb.owned[k] * model.mass[n], rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
      for (int i = 0; i < 3; ++i) {
        rb.first_moment[3 * b + i] += w * r[i];
        for (int j = 0; j < 3; ++j) rb.inertia[9 * b + 3 * i + j] += w * ((i == j ? rr : 0.0) - r[i] * r[j]);
      }
    }
  }
  parallel::sum(rb.first_moment.data(), static_cast<int>(rb.first_moment.size()));
  parallel::sum(rb.inertia.data(), static_cast<int>(rb.inertia.size()));
  Constraints kept;
  auto& c = model.constraints;
  for (std::size_t k = 0; k < c.dof.size(); ++k) {
    if (turning[static_cast<std::size_t>(c.dof[k] / 3)]) continue;
    kept.dof.push_back(c.dof[k]);
    kept.kind.push_back(c.kind[k]);
    kept.function.push_back(c.function[k]);
    kept.scale.push_back(c.scale[k]);
  }
  c = std::move(kept);
}

}  // namespace

void RigidMotion::init(std::size_t bodies) {
  now.assign(size * bodies, 0.0);
  for (std::size_t b = 0; b < bodies; ++b)
    for (int i = 0; i < 3; ++i) now[size * b + Q + 4 * i] = 1.0;
  next = now;
  omega_n.assign(3 * bodies, 0.0);
}

// Rodrigues' formula (docs/theory.md eq. 1.6.4). Below |t| = 1e-4 the series of sin and 1 - cos to the
// term that is still above round-off, so a small step's rotation keeps its digits.
void rotation_matrix(const double t[3], double R[9]) {
  const double a2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2], a = std::sqrt(a2);
  const double s = a < 1e-4 ? 1.0 - a2 / 6.0 : std::sin(a) / a;                // sin a / a
  const double c = a < 1e-4 ? 0.5 - a2 / 24.0 : (1.0 - std::cos(a)) / a2;       // (1 - cos a) / a^2
  const double K[9] = {0.0, -t[2], t[1], t[2], 0.0, -t[0], -t[1], t[0], 0.0};  // [t]x
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double K2 = 0.0;
      for (int k = 0; k < 3; ++k) K2 += K[3 * i + k] * K[3 * k + j];
      R[3 * i + j] = (i == j ? 1.0 : 0.0) + s * K[3 * i + j] + c * K2;
    }
}

// The axis from the skew part, the angle from atan2(|skew|, (tr - 1)/2): accurate at small angles too.
void rotation_vector(const double Q[9], double t[3]) {
  const double w[3] = {0.5 * (Q[7] - Q[5]), 0.5 * (Q[2] - Q[6]), 0.5 * (Q[3] - Q[1])};  // sin a * n
  const double sa = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const double a = std::atan2(sa, 0.5 * (Q[0] + Q[4] + Q[8] - 1.0));
  const double f = sa > 0.0 ? a / sa : 1.0;
  for (int i = 0; i < 3; ++i) t[i] = f * w[i];
}

// Gaussian elimination with partial pivoting on the free rows and columns of A (at most 6), in the unknowns
// (V, l omega) and with the moment rows over l, l = sqrt(tr J / 2M) the body's radius of gyration: every
// block is then of order M (in SI a nm body's J is 1e-17 M), so the pivots compare like with like.
void solve_rigid_velocity(double mass, const double S[3], const double J[9], const double b[6],
                          const unsigned char known[6], double q[6]) {
  const double trace = J[0] + J[4] + J[8];
  const double l = trace > 0.0 ? std::sqrt(0.5 * trace / mass) : 1.0;
  double A[6][6] = {};
  for (int i = 0; i < 3; ++i) {
    A[i][i] = mass;
    for (int j = 0; j < 3; ++j) A[3 + i][3 + j] = J[3 * i + j] / (l * l);
  }
  const double Sx[3][3] = {{0.0, -S[2], S[1]}, {S[2], 0.0, -S[0]}, {-S[1], S[0], 0.0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      A[i][3 + j] = -Sx[i][j] / l;
      A[3 + i][j] = Sx[i][j] / l;
    }
  const double unit[6] = {1.0, 1.0, 1.0, l, l, l};  // z = unit q, rows scaled by 1 / unit
  int f[6], m = 0;
  for (int j = 0; j < 6; ++j)
    if (!known[j]) f[m++] = j;
  double a[6][7];
  for (int r = 0; r < m; ++r) {
    a[r][m] = b[f[r]] / unit[f[r]];
    for (int j = 0; j < 6; ++j)
      if (known[j]) a[r][m] -= A[f[r]][j] * unit[j] * q[j];
    for (int c = 0; c < m; ++c) a[r][c] = A[f[r]][f[c]];
  }
  for (int c = 0; c < m; ++c) {
    int p = c;
    for (int r = c + 1; r < m; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    for (int k = 0; k <= m; ++k) std::swap(a[c][k], a[p][k]);
    for (int r = c + 1; r < m; ++r) {
      const double factor = a[r][c] / a[c][c];
      for (int k = c; k <= m; ++k) a[r][k] -= factor * a[c][k];
    }
  }
  double z[6];
  for (int r = m - 1; r >= 0; --r) {
    double x = a[r][m];
    for (int k = r + 1; k < m; ++k) x -= a[r][k] * z[k];
    z[r] = x / a[r][r];
  }
  for (int r = 0; r < m; ++r) q[f[r]] = z[r] / unit[f[r]];
}

void add_rigid_body_node_sets(mesh::Mesh& mesh, const std::vector<inputs::RigidBodySpec>& bodies) {
  std::vector<int> body_of(static_cast<std::size_t>(mesh.node_count()), -1);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const auto& b = bodies[k];
    std::vector<int> nodes = body_nodes(mesh, b);
    if (nodes.empty()) throw SetupError(b.where.str() + ": error: rigid body '" + b.name + "' has no nodes");
    for (int n : nodes) {
      if (body_of[n] >= 0)
        throw SetupError(b.where.str() + ": error: node " + std::to_string(n + 1) + " is in rigid bodies '" +
                         bodies[body_of[n]].name + "' and '" + b.name + "'; a node belongs to one body at most");
      body_of[n] = static_cast<int>(k);
    }
    // The body's own node set already carries its name (as does a mesh this ran on before).
    if (const auto it = mesh.node_sets.find(b.name); it != mesh.node_sets.end() && it->second == nodes) continue;
    if (mesh.node_sets.count(b.name))
      throw SetupError(b.where.str() + ": error: rigid body '" + b.name + "' has the name of a node set of the mesh " +
                       "with other nodes; name the body differently (its boundary conditions say 'rigid body = NAME')");
    mesh.node_sets[b.name] = std::move(nodes);
  }
}

RigidBodies build_rigid_bodies(const inputs::RegionSpec& region, Model& model) {
  RigidBodies rb;
  const auto& d = model.domain;
  const std::size_t bodies = region.rigid_bodies.size();
  if (bodies == 0) return rb;
  std::vector<char> constrained(3 * model.mass.size(), 0);
  for (int dof : model.constraints.dof) constrained[static_cast<std::size_t>(dof)] = 1;
  // Per body: mass, node count, centroid sums, constrained counts per component: summed over the ranks.
  std::vector<double> sums(8 * bodies, 0.0);
  rb.first.push_back(0);
  for (std::size_t b = 0; b < bodies; ++b) {
    const auto& spec = region.rigid_bodies[b];
    rb.name.push_back(spec.name);
    const auto it = model.mesh.node_sets.find(spec.name);
    if (it != model.mesh.node_sets.end())
      for (int n : it->second) {
        rb.node.push_back(n);
        rb.owned.push_back(d.owned[n]);
        const double w = d.owned[n];
        sums[8 * b] += w * model.mass[n];
        sums[8 * b + 1] += w;
        for (int i = 0; i < 3; ++i) {
          sums[8 * b + 2 + i] += w * model.mesh.coordinates[3 * static_cast<std::size_t>(n) + i];
          sums[8 * b + 5 + i] += w * constrained[3 * static_cast<std::size_t>(n) + i];
        }
      }
    rb.first.push_back(static_cast<int>(rb.node.size()));
  }
  parallel::sum(sums.data(), static_cast<int>(sums.size()));
  add_drives(region, model, rb);
  std::vector<double> body_constrained(3 * bodies);
  for (std::size_t b = 0; b < bodies; ++b) {
    const auto& spec = region.rigid_bodies[b];
    const double* s = &sums[8 * b];
    for (int i = 0; i < 3; ++i) body_constrained[3 * b + i] = s[5 + i];
    rb.mass.push_back(s[0]);
    rb.node_count.push_back(static_cast<int>(s[1] + 0.5));
    for (int i = 0; i < 3; ++i)
      rb.reference.push_back(spec.reference_point ? (*spec.reference_point)[i] : s[2 + i] / s[1]);
    for (int i = 0; i < 3; ++i) {
      const int count = static_cast<int>(s[5 + i] + 0.5);
      if (rb.rotating[b]) {  // add_rotation checks its constraints and moves them to the body
        rb.free.push_back(rb.drive_kind[6 * b + i] ? 0 : 1);
        continue;
      }
      if (count != 0 && count != rb.node_count[b])
        throw SetupError(spec.where.str() + ": error: rigid body '" + spec.name + "': component " + "xyz"[i] + " of " +
                         std::to_string(count) + " of its " + std::to_string(rb.node_count[b]) +
                         " nodes is constrained by a node-set boundary condition; drive the body instead ('rigid "
                         "body = " + spec.name + "' in the boundary condition) or none of its nodes");
      rb.free.push_back(count == 0 ? 1 : 0);
    }
  }
  add_rotation(region, model, body_constrained, rb);
  // Model::nodal_forces holds the deck's prescribed forces in deck order.
  for (std::size_t k = 0; k < region.prescribed_forces.size(); ++k) {
    const auto& p = region.prescribed_forces[k];
    if (p.rigid_body.empty()) continue;
    for (std::size_t b = 0; b < bodies; ++b)
      if (rb.name[b] == p.rigid_body) {
        rb.load_body.push_back(static_cast<int>(b));
        rb.load_index.push_back(static_cast<int>(k));
        rb.load_component.push_back(static_cast<int>(p.component));
      }
  }
  return rb;
}

std::vector<std::string> describe_rigid_bodies(const RigidBodies& rb) {
  std::vector<std::string> lines;
  for (std::size_t b = 0; b < rb.size(); ++b) {
    std::string driven, moving, rotation = "rotation fixed";
    for (int i = 0; i < 3; ++i) (rb.free[3 * b + i] ? moving : driven) += "xyz"[i];
    if (rb.rotating[b]) {
      std::string free_axes, driven_axes, held;
      for (int i = 0; i < 3; ++i)
        (rb.axis_free[3 * b + i] ? free_axes : rb.drive_kind[6 * b + 3 + i] ? driven_axes : held) += "xyz"[i];
      const double* J = &rb.inertia[9 * b];
      rotation = format("rotation free about %s, driven about %s, held about %s (inertia about the reference point "
                        "diag %.6g %.6g %.6g kg m^2)",
                        free_axes.empty() ? "no axis" : free_axes.c_str(), driven_axes.empty() ? "none" : driven_axes.c_str(),
                        held.empty() ? "none" : held.c_str(), J[0], J[4], J[8]);
    }
    lines.push_back(format("  rigid body '%s': %d nodes, mass %.6g kg, reference point (%.6g, %.6g, %.6g) m, %s; "
                           "components %s driven, %s free (moved by the forces on its nodes)",
                           rb.name[b].c_str(), rb.node_count[b], rb.mass[b], rb.reference[3 * b],
                           rb.reference[3 * b + 1], rb.reference[3 * b + 2], rotation.c_str(),
                           driven.empty() ? "none" : driven.c_str(), moving.empty() ? "none" : moving.c_str()));
  }
  return lines;
}

}  // namespace tribex::solver
