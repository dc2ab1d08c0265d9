// SPDX-License-Identifier: MIT
// Kinematic constraints on node sets that meet (solver/setup/build_model.cpp `constrain`): a component
// fixed by two `fixed displacement` blocks is fixed once (a quarter model's symmetry plane crosses the
// fixed bottom; verification/hertz), any other repeat is refused with the deck location of both.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "solver/errors.hpp"
#include "solver/model.hpp"
#include "support.hpp"
#include "tests/support/setup_errors.hpp"

namespace tribex {
namespace {

using C = inputs::Component;

inputs::SourceLocation at(int line) { return {"cube.i", line, 7}; }

// The 2^3 cube (3 x 3 x 3 = 27 nodes): b_zmin (9 nodes) fixed in x, y, z and b_xmin (9 nodes) in x; they
// share the 3 nodes of the edge x = 0, z = 0, whose x is then fixed by both blocks.
TEST(RepeatedConstraint, FixedTwiceIsFixedOnce) {
  auto deck = test::box_deck(2, 1e-8, "elastic", inputs::ElementFormulation::mean_quadrature);
  auto& region = deck.procedure.region;
  region.fixed_displacements.push_back({"b_zmin", {C::x, C::y, C::z}, at(10)});
  region.fixed_displacements.push_back({"b_xmin", {C::x}, at(14)});
  const solver::Model model = solver::build_model(deck);
  const auto& dofs = model.constraints.dof;
  EXPECT_EQ(dofs.size(), 27u + 9u - 3u);  // 27 of the bottom, 9 - 3 new ones of the side
  EXPECT_EQ(std::set<int>(dofs.begin(), dofs.end()).size(), dofs.size());  // each dof once
  EXPECT_TRUE(std::all_of(model.constraints.kind.begin(), model.constraints.kind.end(),
                          [](auto k) { return k == solver::Constraints::Kind::fixed; }));
}

// A driven component that is also fixed has no single meaning: refused, naming both blocks, in either
// role (the fixed block is applied first whatever the deck's order).
TEST(RepeatedConstraint, DrivenAndFixedIsRefused) {
  auto deck = test::box_deck(2, 1e-8, "elastic", inputs::ElementFormulation::mean_quadrature);
  deck.functions.push_back({"push", {0.0, 1.0}, {0.0, 1e-9}, {}});
  auto& region = deck.procedure.region;
  region.fixed_displacements.push_back({"b_zmin", {C::x, C::y, C::z}, at(10)});
  region.prescribed_motions.push_back(
      {inputs::PrescribedMotionSpec::Kind::displacement, "b_xmin", C::x, "push", 1.0, at(20), {}});
  const std::string message = test::setup_error_of([&] { solver::build_model(deck); });
  EXPECT_NE(message.find("cube.i:20:7: error: node "), std::string::npos) << message;
  EXPECT_NE(message.find(" component x is already constrained at cube.i:10:7;"), std::string::npos) << message;
}

TEST(RepeatedConstraint, DrivenTwiceIsRefused) {
  auto deck = test::box_deck(2, 1e-8, "elastic", inputs::ElementFormulation::mean_quadrature);
  deck.functions.push_back({"push", {0.0, 1.0}, {0.0, 1e-9}, {}});
  auto& region = deck.procedure.region;
  using K = inputs::PrescribedMotionSpec::Kind;
  region.prescribed_motions.push_back({K::displacement, "b_zmax", C::z, "push", 1.0, at(20), {}});
  region.prescribed_motions.push_back({K::velocity, "b_xmin", C::z, "push", 1.0, at(26), {}});
  const std::string message = test::setup_error_of([&] { solver::build_model(deck); });
  EXPECT_NE(message.find("cube.i:26:7: error: node "), std::string::npos) << message;
  EXPECT_NE(message.find(" component z is already constrained at cube.i:20:7;"), std::string::npos) << message;
}

}  // namespace
}  // namespace tribex
