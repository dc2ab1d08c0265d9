// SPDX-License-Identifier: MIT
// Which way the contact zone travels (solver/parallel/contact_travel.hpp), and the partition's coordinate scale
// the run takes from it where the deck gives none.
#include <gtest/gtest.h>

#include <string>

#include "mesh/box.hpp"
#include "solver/parallel/contact_travel.hpp"
#include "tests/solver/support.hpp"

using namespace tribex;

namespace {

// A 12 x 12 x 4 block, a 6 x 6 x 2 indenter on its top (contact: the indenter's bottom on the block's
// top), and a loose 2 x 2 x 1 box above, touching neither.
mesh::Mesh block_indenter_and_loose_box() {
  mesh::BoxSpec block, indenter, loose;
  block.name = "block";
  block.size = {12, 12, 4};
  block.intervals = {12, 12, 4};
  indenter.name = "indenter";
  indenter.origin = {3, 3, 4};
  indenter.size = {6, 6, 2};
  indenter.intervals = {6, 6, 2};
  loose.name = "loose";
  loose.origin = {0, 0, 10};
  loose.size = {2, 2, 1};
  loose.intervals = {2, 2, 1};
  mesh::Mesh m = mesh::generate_box(block);
  mesh::append(m, mesh::generate_box(indenter));
  mesh::append(m, mesh::generate_box(loose));
  return m;
}

inputs::PrescribedMotionSpec motion(const std::string& set, inputs::Component c, const std::string& function,
                                    double scale,
                                    inputs::PrescribedMotionSpec::Kind kind = inputs::PrescribedMotionSpec::Kind::displacement) {
  inputs::PrescribedMotionSpec p;
  p.kind = kind;
  p.node_set = set;
  p.component = c;
  p.function = function;
  p.scale_factor = scale;
  return p;
}

// Functions: ramp 0 -> 1 over t 0..1; there_and_back 0 -> 1 -> 0 over t 0..2; reversing (a velocity)
// 1 -> -1 over t 0..1. The run ends at `termination`.
inputs::Deck indenter_deck(double termination = 1.0) {
  inputs::Deck deck;
  deck.functions.push_back({"ramp", {0, 1}, {0, 1}, {}});
  deck.functions.push_back({"there_and_back", {0, 1, 2}, {0, 1, 0}, {}});
  deck.functions.push_back({"reversing", {0, 1}, {1, -1}, {}});
  deck.procedure.time_control.termination_time = termination;
  deck.procedure.region.contact = test::one_contact("tip", "indenter_zmin", "top", "block_zmax");
  return deck;
}

}  // namespace

TEST(ContactTravel, TheFarthestTangentialMotionOfAContactBody) {
  const mesh::Mesh m = block_indenter_and_loose_box();
  inputs::Deck deck = indenter_deck();
  auto& motions = deck.procedure.region.prescribed_motions;
  // Pressed 50 along z (the contact normal: not travel), slid 30 along x; the loose box, which holds
  // no contact surface, moved 100 along y.
  motions.push_back(motion("indenter_zmax", inputs::Component::z, "ramp", -50));
  motions.push_back(motion("indenter_zmax", inputs::Component::x, "ramp", 30));
  motions.push_back(motion("loose_zmax", inputs::Component::y, "ramp", 100));
  const auto travel = solver::contact_travel(deck, m);
  ASSERT_TRUE(travel.has_value());
  EXPECT_EQ(travel->axis, 0);
  EXPECT_DOUBLE_EQ(travel->distance, 30.0);
  EXPECT_EQ(travel->node_set, "indenter_zmax");
  EXPECT_EQ(travel->normal_axis, 2);
  EXPECT_DOUBLE_EQ(travel->zone_extent, 6.0) << "the indenter's bottom, x = 3 .. 9";
  // Without a `coordinate scale` the cuts follow it; the deck's scale, where given, is kept.
  inputs::DecompositionSpec decomposition;
  EXPECT_EQ(solver::decomposition_scale(decomposition, travel, 2),
            (solver::parallel::AxisScale{solver::kTravelScale, 1, 1}));
  decomposition.coordinate_scale = std::array<double, 3>{1, 1, 1};
  EXPECT_EQ(solver::decomposition_scale(decomposition, travel, 2), (solver::parallel::AxisScale{1, 1, 1}));
}

TEST(ContactTravel, ASlideShorterThanAPatchKeepsTheCuts) {
  const mesh::Mesh m = block_indenter_and_loose_box();
  inputs::Deck deck = indenter_deck();
  // Slid 1 along x under a 6 wide indenter: the patches are 3 wide at 2 ranks (the zone stays on
  // them), 0.75 wide at 8 (it crosses them).
  deck.procedure.region.prescribed_motions.push_back(motion("indenter_zmax", inputs::Component::x, "ramp", 1));
  const auto travel = solver::contact_travel(deck, m);
  ASSERT_TRUE(travel.has_value());
  EXPECT_FALSE(solver::crosses_patches(*travel, 2));
  EXPECT_FALSE(solver::crosses_patches(*travel, 6)) << "exactly a patch's width";
  EXPECT_TRUE(solver::crosses_patches(*travel, 8));
  EXPECT_EQ(solver::decomposition_scale({}, travel, 2), (solver::parallel::AxisScale{1, 1, 1}));
  EXPECT_EQ(solver::decomposition_scale({}, travel, 8), (solver::parallel::AxisScale{solver::kTravelScale, 1, 1}));
}

TEST(ContactTravel, NoneWithoutTangentialMotionOrContact) {
  const mesh::Mesh m = block_indenter_and_loose_box();
  inputs::Deck deck = indenter_deck();
  deck.procedure.region.prescribed_motions.push_back(motion("indenter_zmax", inputs::Component::z, "ramp", -50));
  EXPECT_FALSE(solver::contact_travel(deck, m).has_value()) << "an indentation does not travel";
  EXPECT_EQ(solver::decomposition_scale({}, solver::contact_travel(deck, m), 4), (solver::parallel::AxisScale{1, 1, 1}));
  deck.procedure.region.prescribed_motions.push_back(motion("indenter_zmax", inputs::Component::y, "ramp", 0));
  EXPECT_FALSE(solver::contact_travel(deck, m).has_value()) << "a motion of zero distance";
  deck.procedure.region.prescribed_motions.push_back(motion("indenter_zmax", inputs::Component::y, "ramp", 5));
  EXPECT_TRUE(solver::contact_travel(deck, m).has_value());
  deck.procedure.region.contact.reset();
  EXPECT_FALSE(solver::contact_travel(deck, m).has_value()) << "no contact definition";
}

TEST(ContactTravel, DistanceIsTheTotalVariationOverTheRun) {
  const mesh::Mesh m = block_indenter_and_loose_box();
  // There and back along y, scale 5: 5 out by t = 1, 2.5 back by the end at t = 1.5.
  inputs::Deck deck = indenter_deck(1.5);
  deck.procedure.region.prescribed_motions.push_back(motion("indenter_zmax", inputs::Component::y, "there_and_back", 5));
  auto travel = solver::contact_travel(deck, m);
  ASSERT_TRUE(travel.has_value());
  EXPECT_EQ(travel->axis, 1);
  EXPECT_DOUBLE_EQ(travel->distance, 7.5);
  // A velocity 2 (1 - 2t) along x: the integral of its magnitude, 0.5 out and 0.5 back by t = 1, split
  // at the zero; a block side's node set moves the block, which holds the track.
  deck = indenter_deck(1.0);
  deck.procedure.region.prescribed_motions.push_back(
      motion("block_xmin", inputs::Component::x, "reversing", 2, inputs::PrescribedMotionSpec::Kind::velocity));
  travel = solver::contact_travel(deck, m);
  ASSERT_TRUE(travel.has_value());
  EXPECT_EQ(travel->axis, 0);
  EXPECT_NEAR(travel->distance, 1.0, 1e-15);
  EXPECT_EQ(travel->node_set, "block_xmin");
}
