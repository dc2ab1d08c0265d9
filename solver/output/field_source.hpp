// SPDX-License-Identifier: MIT
// What the result-field getters (inputs/result_fields.hpp) read at an output time: the integrator's
// nodal arrays, the contact's per-surface-node arrays and the blocks' element outputs, each handed
// back as this rank's rows in the order results.h5 and results.exo take them (a parallel run's owned
// nodes; its elements). The buffers are kept from one output to the next (no allocation once sized).
#pragma once

#include <deque>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "inputs/result_fields.hpp"
#include "solver/integrators/central_difference.hpp"
#include "solver/model.hpp"
#include "solver/output/results_writer.hpp"

namespace tribex::solver {

class FieldSource {
 public:
  using Values = std::optional<std::span<const double>>;

  /// `surface_index` [local node] the node's row in the contact's numbering, -1: none.
  FieldSource(const Model& model, const CentralDifference& stepper, const std::vector<int>& surface_index)
      : integrator(stepper), contact(model.contact.get()), model_(model), surface_index_(surface_index) {}

  const CentralDifference& integrator;
  const contact::ContactManager* contact;  // nullptr: the model has no contact

  /// Called once per output time, before the getters: the scratch buffers are reused from the first.
  void start_output() { next_ = 0; }
  Values none() const { return std::nullopt; }
  Values values(const std::vector<double>& v) const { return std::span<const double>(v); }
  /// The owned nodes' rows of `local` [local node][components] (serial: `local` itself).
  Values nodal(const std::vector<double>& local, int components);
  /// The owned nodes' rows of `per_surface_node` [contact node][components]; `fill` on nodes of no
  /// contact surface.
  Values contact_rows(const std::vector<double>& per_surface_node, int components, double fill);
  /// [element][6] Cauchy stress, Voigt xx yy zz xy yz zx, Pa; [element] equivalent plastic strain.
  Values element_stress();
  Values element_plastic_strain();
  /// [node][3] the rigid-body coupling forces c_i = g_i + R_i + s_i of docs/theory.md 1.6 (0 off the bodies),
  /// N; none without a rigid body.
  Values rigid_body_force();
  /// A buffer of its own for each call within one output (kept for the next output).
  std::vector<double>& scratch();

 private:
  const Model& model_;
  const std::vector<int>& surface_index_;
  std::deque<std::vector<double>> buffers_;  // a deque: growing it keeps the earlier buffers where they are
  std::size_t next_ = 0;
  std::vector<double> stress_, plastic_strain_;
};

/// Appends to `out` the fields `names` of `kind` (deck words, checked by the schema against the
/// table) in the deck's order, each with its table row's components and SI unit; a field whose
/// getter has nothing (no contact) is left out.
void collect_fields(const std::vector<std::string>& names, inputs::FieldKind kind, FieldSource& source,
                    std::vector<FieldView>& out);

}  // namespace tribex::solver
