// SPDX-License-Identifier: MIT
#include "solver/setup/rigid_bodies.hpp"

#include <algorithm>
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

}  // namespace

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

RigidBodies build_rigid_bodies(const inputs::RegionSpec& region, const Model& model) {
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
  for (std::size_t b = 0; b < bodies; ++b) {
    const auto& spec = region.rigid_bodies[b];
    const double* s = &sums[8 * b];
    rb.mass.push_back(s[0]);
    rb.node_count.push_back(static_cast<int>(s[1] + 0.5));
    for (int i = 0; i < 3; ++i)
      rb.reference.push_back(spec.reference_point ? (*spec.reference_point)[i] : s[2 + i] / s[1]);
    for (int i = 0; i < 3; ++i) {
      const int count = static_cast<int>(s[5 + i] + 0.5);
      if (count != 0 && count != rb.node_count[b])
        throw SetupError(spec.where.str() + ": error: rigid body '" + spec.name + "': component " + "xyz"[i] + " of " +
                         std::to_string(count) + " of its " + std::to_string(rb.node_count[b]) +
                         " nodes is constrained by a node-set boundary condition; drive the body instead ('rigid "
                         "body = " + spec.name + "' in the boundary condition) or none of its nodes");
      rb.free.push_back(count == 0 ? 1 : 0);
    }
  }
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
    std::string driven, moving;
    for (int i = 0; i < 3; ++i) (rb.free[3 * b + i] ? moving : driven) += "xyz"[i];
    lines.push_back(format("  rigid body '%s': %d nodes, mass %.6g kg, reference point (%.6g, %.6g, %.6g) m, rotation "
                           "fixed; components %s driven, %s free (moved by the forces on its nodes)",
                           rb.name[b].c_str(), rb.node_count[b], rb.mass[b], rb.reference[3 * b],
                           rb.reference[3 * b + 1], rb.reference[3 * b + 2], driven.empty() ? "none" : driven.c_str(),
                           moving.empty() ? "none" : moving.c_str()));
  }
  return lines;
}

}  // namespace tribex::solver
