// SPDX-License-Identifier: MIT
// Unit-aware numbers for decks and command lines: "27 nm", "161 GPa", "0.05 J/m^2",
// "2330 kg/m^3", "1 m/s", "10 ps", "1e8 1/s". Plain numbers are SI and dimensionless until a key
// gives them a dimension. Units are products/quotients of SI base or derived symbols
// (m s g N Pa J W Hz V) with SI prefixes (f p n u µ m c k M G T), an optional integer power `^n`
// per factor, `*` or `.` between factors and at most one `/` (everything after it is divided).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace tribex::inputs {

/// Exponents of the SI base dimensions kg, m, s (A for volts is not needed here and rejected).
struct Dimension {
  int mass = 0;
  int length = 0;
  int time = 0;
  friend bool operator==(const Dimension&, const Dimension&) = default;
  /// Human form: "m", "Pa", "kg/m^3", "m/s", "dimensionless", else "kg^a m^b s^c".
  std::string str() const;
};

namespace dim {
inline constexpr Dimension none{0, 0, 0};
inline constexpr Dimension mass{1, 0, 0};
inline constexpr Dimension length{0, 1, 0};
inline constexpr Dimension area{0, 2, 0};
inline constexpr Dimension time{0, 0, 1};
inline constexpr Dimension rate{0, 0, -1};  // 1/s
inline constexpr Dimension velocity{0, 1, -1};
inline constexpr Dimension force{1, 1, -2};
inline constexpr Dimension pressure{1, -1, -2};
inline constexpr Dimension energy{1, 2, -2};
inline constexpr Dimension energy_per_area{1, 0, -2};  // J/m^2 = N/m
inline constexpr Dimension stiffness{1, 0, -2};        // N/m, same as energy per area
inline constexpr Dimension density{1, -3, 0};
inline constexpr Dimension per_area{0, -2, 0};  // 1/m^2 (summit density)
}  // namespace dim

struct Quantity {
  double value = 0.0;  // SI
  Dimension dimension;
};

/// Parse a unit expression ("nm", "GPa", "J/m^2"); returns the factor to SI and its dimension,
/// or nullopt and a reason in *error.
std::optional<Quantity> parse_unit(std::string_view unit, std::string* error);

/// Parse a number with an optional unit, with or without a space ("27 nm", "27nm", "-1.5e-3").
/// Returns nullopt and a reason in *error for anything else (trailing junk, unknown unit, NaN/inf).
std::optional<Quantity> parse_quantity(std::string_view text, std::string* error);

}  // namespace tribex::inputs
