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
