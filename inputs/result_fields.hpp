// SPDX-License-Identifier: MIT
// The result fields (`nodal variables`, `element variables` of `begin results output`) as one
// table: name, kind, components, SI unit, one-line definition, getter. The deck schema's allowed
// values (schema.cpp), the fields a run writes (solver/run/deck_run_loop.cpp write_fields), their
// names in results.h5/.xdmf and results.exo, and `tribex run --list-fields` all come from it, so a
// field is added here as one row and nowhere else (solver/output/README.md, "Result fields").
//
// Each getter is a generic lambda over the solver's `FieldSource` (solver/output/field_source.hpp):
// it is instantiated only where the solver writes the fields, so this header needs nothing of the
// solver and the deck layer reads the names, units and definitions alone. A getter returns this
// rank's rows ([node][components] of its owned nodes, or [element][components] of its elements),
// or `s.none()` where the model has no such field (the contact fields of a run without contact:
// the field is then not written).
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace tribex::inputs {

enum class FieldKind { nodal, element };

/// Von Mises equivalent stress of a Cauchy stress in Voigt order xx yy zz xy yz zx, Pa:
/// sqrt(3/2 s:s), s = dev sigma (docs/theory.md 12.1, eq. 12.1).
inline double von_mises_stress(const double* v) {
  const double dxy = v[0] - v[1], dyz = v[1] - v[2], dzx = v[2] - v[0];
  return std::sqrt(0.5 * (dxy * dxy + dyz * dyz + dzx * dzx) + 3.0 * (v[3] * v[3] + v[4] * v[4] + v[5] * v[5]));
}

template <class Get>
struct ResultField {
  std::string_view name;        // deck word, results.h5 dataset, XDMF attribute, Exodus variable (+ _x ... suffixes)
  FieldKind kind;
  int components;               // 1 scalar, 3 vector x y z, 6 symmetric tensor (Voigt xx yy zz xy yz zx)
  std::string_view unit;        // SI; "m" fields are written in the results' length unit
  std::string_view definition;  // one line (`tribex run --list-fields`, the README legend)
  Get get;                      // get(FieldSource&) -> std::optional<std::span<const double>>
};
template <class Get>
ResultField(std::string_view, FieldKind, int, std::string_view, std::string_view, Get) -> ResultField<Get>;

// The rows, in the order `--list-fields` prints them (the deck's order decides the files' order).
inline constexpr auto result_field_table = std::make_tuple(
    ResultField{"displacement", FieldKind::nodal, 3, "m", "displacement u = x - X",
                [](auto& s) { return s.nodal(s.integrator.displacement(), 3); }},
    ResultField{"velocity", FieldKind::nodal, 3, "m/s", "velocity v^n (docs/theory.md 1.3)",
                [](auto& s) { return s.nodal(s.integrator.velocity(), 3); }},
    ResultField{"acceleration", FieldKind::nodal, 3, "m/s^2", "acceleration (v^{n+1/2} - v^{n-1/2}) / dt^n",
                [](auto& s) { return s.nodal(s.integrator.acceleration(), 3); }},
    ResultField{"force", FieldKind::nodal, 3, "N", "nodal force f^n: internal + applied loads + contact",
                [](auto& s) { return s.nodal(s.integrator.force(), 3); }},
    ResultField{"rigid_body_force", FieldKind::nodal, 3, "N",
                "force a rigid body's reference point applies to a node of the body (coupling force, constraint "
                "reaction, share of a prescribed force on the body; docs/theory.md 1.6); at rest, the force the body "
                "puts into the rest of the model there; 0 off rigid bodies (not written without one)",
                [](auto& s) { return s.rigid_body_force(); }},
    ResultField{"contact_traction", FieldKind::nodal, 3, "Pa",
                "contact force on a slave node over its tributary area (normal + tangential; a symmetric "
                "interaction's pass gives half; 0 off the slave surfaces)",
                [](auto& s) { return s.contact ? s.contact_rows(s.contact->traction(), 3, 0.0) : s.none(); }},
    ResultField{"contact_status", FieldKind::nodal, 1, "1", "1 where a slave node is in contact, else 0",
                [](auto& s) { return s.contact ? s.contact_rows(s.contact->status(), 1, 0.0) : s.none(); }},
    ResultField{"contact_pressure", FieldKind::nodal, 1, "Pa",
                "normal contact pressure -t.n/phi (n the slave surface's outward node normal, phi the pass factor: "
                "1/2 symmetric, else 1), compressive positive, adhesive negative; 0 off the slave surfaces",
                [](auto& s) {
                  if (!s.contact) return s.none();
                  std::vector<double>& p = s.scratch();
                  s.contact->normal_pressure(s.integrator.contact_positions().data(), p);
                  return s.contact_rows(p, 1, 0.0);
                }},
    ResultField{"gap", FieldKind::nodal, 1, "m",
                "normal gap of a slave node to the master face it projects on, negative in penetration; NaN "
                "where the node is no slave node or has no master face within the search margin",
                [](auto& s) {
                  if (!s.contact) return s.none();
                  std::vector<double>& g = s.scratch();
                  s.contact->node_gaps(g);
                  return s.contact_rows(g, 1, std::numeric_limits<double>::quiet_NaN());
                }},
    ResultField{"stress", FieldKind::element, 6, "Pa", "Cauchy stress, element mean (Voigt xx yy zz xy yz zx)",
                [](auto& s) { return s.element_stress(); }},
    ResultField{"von_mises", FieldKind::element, 1, "Pa", "von Mises stress sqrt(3/2 s:s) of the element stress",
                [](auto& s) {
                  const std::span<const double> sigma = *s.element_stress();
                  std::vector<double>& out = s.scratch();
                  out.resize(sigma.size() / 6);
                  for (std::size_t e = 0; e < out.size(); ++e) out[e] = von_mises_stress(&sigma[6 * e]);
                  return s.values(out);
                }},
    ResultField{"equivalent_plastic_strain", FieldKind::element, 1, "1",
                "equivalent plastic strain alpha, element mean (J2 plasticity, docs/theory.md 3.3; 0 elsewhere)",
                [](auto& s) { return s.element_plastic_strain(); }});

/// Calls f(row) for every row of the table, in order.
template <class F>
void for_each_result_field(F&& f) {
  std::apply([&](const auto&... row) { (f(row), ...); }, result_field_table);
}

/// The names of the fields of `kind`, in table order (the deck's allowed values).
inline std::vector<std::string> result_field_names(FieldKind kind) {
  std::vector<std::string> names;
  for_each_result_field([&](const auto& row) {
    if (row.kind == kind) names.emplace_back(row.name);
  });
  return names;
}

}  // namespace tribex::inputs
