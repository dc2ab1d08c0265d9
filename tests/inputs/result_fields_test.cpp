// SPDX-License-Identifier: MIT
// The result-field table (inputs/result_fields.hpp): the von Mises formula against closed forms, the
// rows well formed, and the schema's `nodal variables` / `element variables` exactly its names.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "inputs/result_fields.hpp"
#include "inputs/schema.hpp"

namespace tribex::inputs {
namespace {

TEST(ResultFields, VonMisesOfClosedFormStates) {
  const double uniaxial[6] = {0, 0, -250e6, 0, 0, 0};
  EXPECT_DOUBLE_EQ(von_mises_stress(uniaxial), 250e6);  // |sigma|
  const double shear[6] = {0, 0, 0, 0, 40e6, 0};
  EXPECT_DOUBLE_EQ(von_mises_stress(shear), std::sqrt(3.0) * 40e6);  // sqrt(3) tau
  const double hydrostatic[6] = {-3e9, -3e9, -3e9, 0, 0, 0};
  EXPECT_EQ(von_mises_stress(hydrostatic), 0.0);
  // Equibiaxial + shear in another plane: sqrt(s^2 + 3 tau^2) for sigma_xx = sigma_yy = s.
  const double mixed[6] = {100e6, 100e6, 0, 0, 0, 30e6};
  EXPECT_NEAR(von_mises_stress(mixed), std::sqrt(100e6 * 100e6 + 3 * 30e6 * 30e6), 1e-6);
  // A plain pressure added changes nothing (deviatoric).
  const double shifted[6] = {100e6 - 7e8, 100e6 - 7e8, -7e8, 0, 0, 30e6};
  EXPECT_NEAR(von_mises_stress(shifted), von_mises_stress(mixed), 1e-6);
}

TEST(ResultFields, RowsAreWellFormed) {
  std::set<std::string> names;
  int rows = 0;
  for_each_result_field([&](const auto& row) {
    ++rows;
    EXPECT_TRUE(names.insert(std::string(row.name)).second) << row.name;
    EXPECT_TRUE(row.components == 1 || row.components == 3 || row.components == 6) << row.name;
    EXPECT_FALSE(row.unit.empty()) << row.name;
    EXPECT_FALSE(row.definition.empty()) << row.name;
    EXPECT_EQ(row.name.find(' '), std::string_view::npos) << row.name;  // one deck word, a plain array name
  });
  EXPECT_EQ(rows, 12);
  EXPECT_TRUE(names.count("von_mises") && names.count("contact_pressure") && names.count("gap") &&
              names.count("rigid_body_force"));
}

TEST(ResultFields, SchemaChoicesAreTheTableNames) {
  for (const BlockSchema& b : all_block_schemas()) {
    if (b.type != "results output") continue;
    for (const KeySchema& k : b.keys) {
      if (k.name == "nodal variables") {
        EXPECT_EQ(k.allowed, result_field_names(FieldKind::nodal));
      }
      if (k.name == "element variables") {
        EXPECT_EQ(k.allowed, result_field_names(FieldKind::element));
      }
    }
    return;
  }
  FAIL() << "no 'results output' block in the schema";
}

}  // namespace
}  // namespace tribex::inputs
