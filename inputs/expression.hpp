// SPDX-License-Identifier: MIT
// Arithmetic with units for deck parameters (`{W = 0.05 J/m^2}`, `{2*W}`; inputs/README.md,
// "Parameters"): numbers with an optional unit right after them ("0.05 J/m^2", "15nm"; a blank or
// an operator that cannot continue the unit ends it), names of parameters, + - * / ^, unary minus,
// parentheses. Dimensions are carried and checked: + and - need equal dimensions, ^ needs a
// dimensionless exponent (an integer one when the base has a dimension).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "inputs/units.hpp"

namespace tribex::inputs {

/// The value of a name, or nullptr when it is not defined.
using NameLookup = std::function<const Quantity*(std::string_view name)>;

/// Evaluates `text`; nullopt and one line in *error (the problem and the fix) when it is not a
/// valid expression, names an undefined parameter, mixes dimensions or is not finite.
std::optional<Quantity> evaluate_expression(std::string_view text, const NameLookup& lookup, std::string* error);

/// A unit text parse_unit reads back for `d` ("m", "J/m^2", "kg^1*m^-1*s^-2"); "" when dimensionless.
std::string si_unit_text(const Dimension& d);

/// True for a parameter name: a letter or `_`, then letters, digits, `_`.
bool is_parameter_name(std::string_view name);

}  // namespace tribex::inputs
