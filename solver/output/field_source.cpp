// SPDX-License-Identifier: MIT
#include "solver/output/field_source.hpp"

#include <algorithm>
#include <stdexcept>

#include "solver/element_block.hpp"

namespace tribex::solver {

std::vector<double>& FieldSource::scratch() {
  if (buffers_.size() <= next_) buffers_.emplace_back();
  return buffers_[next_++];
}

FieldSource::Values FieldSource::nodal(const std::vector<double>& local, int components) {
  const auto& domain = model_.domain;
  if (domain.serial()) return std::span<const double>(local);
  std::vector<double>& buffer = scratch();
  buffer.clear();
  for (int l : domain.owned_local_nodes())
    buffer.insert(buffer.end(), local.begin() + components * l, local.begin() + components * (l + 1));
  return std::span<const double>(buffer);
}

FieldSource::Values FieldSource::contact_rows(const std::vector<double>& per_surface_node, int components, double fill) {
  const auto& owned = model_.domain.owned_local_nodes();
  std::vector<double>& buffer = scratch();
  buffer.assign(static_cast<std::size_t>(components) * owned.size(), fill);
  std::size_t row = 0;
  for (int l : owned) {
    if (const int k = surface_index_[static_cast<std::size_t>(l)]; k >= 0)
      std::copy(per_surface_node.begin() + components * k, per_surface_node.begin() + components * (k + 1),
                buffer.begin() + components * row);
    ++row;
  }
  return std::span<const double>(buffer);
}

FieldSource::Values FieldSource::element_stress() {
  stress_.resize(6 * static_cast<std::size_t>(model_.mesh.element_count()));
  for (const auto& b : model_.blocks) std::copy(b.stress.begin(), b.stress.end(), stress_.begin() + 6 * b.first_element);
  return std::span<const double>(stress_);
}

FieldSource::Values FieldSource::element_plastic_strain() {
  plastic_strain_.resize(static_cast<std::size_t>(model_.mesh.element_count()));
  for (const auto& b : model_.blocks) equivalent_plastic_strain(b, plastic_strain_.data() + b.first_element);
  return std::span<const double>(plastic_strain_);
}

// As the history's reaction (output/rigid_body_history.cpp), per node: the coupling force, the constraint
// reaction of a driven component and the node's share of the prescribed forces on its body, at time n.
FieldSource::Values FieldSource::rigid_body_force() {
  const RigidBodies& rb = model_.rigid_bodies;
  if (rb.empty()) return none();
  std::vector<double>& c = scratch();
  c.assign(3 * static_cast<std::size_t>(model_.mesh.node_count()), 0.0);
  const auto& coupling = integrator.rigid_coupling_force();
  const auto& reaction = integrator.reaction();
  for (std::size_t b = 0; b < rb.size(); ++b) {
    double share[3] = {0.0, 0.0, 0.0};
    for (std::size_t l = 0; l < rb.load_body.size(); ++l)
      if (rb.load_body[l] == static_cast<int>(b)) {
        const NodalForceLoad& load = model_.nodal_forces[rb.load_index[l]];
        share[rb.load_component[l]] += load.scale * model_.functions[load.function](integrator.time());
      }
    for (int k = rb.first[b]; k < rb.first[b + 1]; ++k) {
      const auto n = static_cast<std::size_t>(rb.node[k]);
      for (int i = 0; i < 3; ++i)
        c[3 * n + i] = coupling[3 * static_cast<std::size_t>(k) + i] + reaction[3 * n + i] + share[i];
    }
  }
  return nodal(c, 3);
}

void collect_fields(const std::vector<std::string>& names, inputs::FieldKind kind, FieldSource& source,
                    std::vector<FieldView>& out) {
  for (const auto& name : names)
    inputs::for_each_result_field([&](const auto& row) {
      if (row.kind != kind || row.name != name) return;
      const FieldSource::Values values = row.get(source);
      if (!values) return;
      if (values->size() % static_cast<std::size_t>(row.components) != 0)
        throw std::logic_error("result field '" + name + "': " + std::to_string(values->size()) +
                               " values are not whole rows of " + std::to_string(row.components));
      out.push_back({name, row.components, *values, std::string(row.unit)});
    });
}

}  // namespace tribex::solver
