// SPDX-License-Identifier: MIT
// One table per output data struct: each row names a field, gives its SI unit and a one-line
// definition, and how to read it (and, where restart files must restore it, how to set it). The
// writers (summary.json, restart archives, history.csv's columns that mirror a field) walk the
// table, so a field is added in one place: its row. The tables are in output_tables.hpp.
#pragma once

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "solver/errors.hpp"

namespace tribex::solver {

template <class T>
struct Field {
  std::string_view name;        // key in summary.json (snake_case); position in a restart array is the row's
  std::string_view unit;        // SI; "-" a pure number, "count" a number of things, "" not a number
  std::string_view definition;  // one line
  double (*get)(const T&) = nullptr;      // the value as a number (nullptr: not a number, see json)
  void (*set)(T&, double) = nullptr;      // restart read-back (nullptr: not kept in restart files)
  std::string (*json)(const T&) = nullptr;  // summary.json text when it is not the plain number (nullptr: the number)
};

namespace detail {
template <auto Member>
struct MemberOf;
template <class C, class V, V C::*M>
struct MemberOf<M> {
  using Class = C;
  using Value = V;
};
}  // namespace detail

/// The row of a data member: read as a double and set back from one (integers and enumerations
/// are exact in a double), so that a restart file restores it bit for bit.
template <auto Member>
constexpr Field<typename detail::MemberOf<Member>::Class> field(std::string_view name, std::string_view unit,
                                                                std::string_view definition) {
  using C = typename detail::MemberOf<Member>::Class;
  using V = typename detail::MemberOf<Member>::Value;
  return {name, unit, definition,
          [](const C& x) {
            if constexpr (std::is_enum_v<V>)
              return static_cast<double>(static_cast<std::underlying_type_t<V>>(x.*Member));
            else
              return static_cast<double>(x.*Member);
          },
          [](C& x, double v) {
            if constexpr (std::is_enum_v<V>)
              x.*Member = static_cast<V>(static_cast<std::underlying_type_t<V>>(v));
            else
              x.*Member = static_cast<V>(v);
          }};
}

/// The row named `name` (a table's rows are looked up by name only while tables are being built).
template <class T>
const Field<T>& field_named(std::span<const Field<T>> table, std::string_view name) {
  for (const Field<T>& f : table)
    if (f.name == name) return f;
  throw std::logic_error("no output field '" + std::string(name) + "'");
}

/// The fields that restart files keep (those with a setter), in table order, as one flat array.
template <class T>
void append_stored(std::span<const Field<T>> table, const T& x, std::vector<double>& out) {
  for (const Field<T>& f : table)
    if (f.set) out.push_back(f.get(x));
}

template <class T>
std::size_t stored_count(std::span<const Field<T>> table) {
  std::size_t n = 0;
  for (const Field<T>& f : table) n += f.set ? 1 : 0;
  return n;
}

/// The inverse of append_stored: sets x's stored fields from values[0 .. stored_count). Fields
/// without a setter are left as they are.
template <class T>
void restore_stored(std::span<const Field<T>> table, const double* values, T& x) {
  std::size_t k = 0;
  for (const Field<T>& f : table)
    if (f.set) f.set(x, values[k++]);
}

/// The whole struct as one restart array, and back; `what` names it in the error for an array
/// of another length (a restart file of a tribex whose table had other rows).
template <class T>
std::vector<double> stored_array(std::span<const Field<T>> table, const T& x) {
  std::vector<double> out;
  append_stored(table, x, out);
  return out;
}

template <class T>
void restore_array(std::span<const Field<T>> table, const std::vector<double>& values, T& x, const std::string& what) {
  const std::size_t n = stored_count(table);
  if (values.size() != n)
    throw SetupError("restart file: " + what + " has " + std::to_string(values.size()) + " values, this tribex keeps " +
                     std::to_string(n) + " (a restart file of another tribex version: resume with the tribex that wrote it)");
  restore_stored(table, values.data(), x);
}

}  // namespace tribex::solver
