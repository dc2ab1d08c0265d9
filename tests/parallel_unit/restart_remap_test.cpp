// SPDX-License-Identifier: MIT
// Restart on another rank count (solver/restart/restart_remap.hpp, issue 57): the writers' groups moved
// onto a rank's partition by global number. Every value is moved, not computed, so every check is
// exact (bitwise): the round-off of a resumed run comes from the new partition's sums, not from here.
// The runs under mpiexec (N -> M ranks against an uninterrupted M-rank run) are tests/parallel's
// mpi_restart_*_npN_to_npM.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "solver/element_block.hpp"
#include "solver/errors.hpp"
#include "solver/restart/restart_remap.hpp"
#include "solver/restart/state_archive.hpp"

using namespace tribex::solver;

namespace {

// A value that names its writer, global number and component, so that any misplacement shows.
double tag(int writer, int global, int k) { return 1000.0 * writer + 10.0 * global + k + 0.125; }

/// Writer `w` holding global nodes `nodes` and global elements `elements` (one block, stateless unless
/// state_width > 0, plain records), nodal fields u (3 per node) and a partial "energies" array.
StateArchive writer(int w, const std::vector<int>& nodes, const std::vector<int>& elements, int state_width = 0) {
  StateArchive a;
  a.put_ints("global_node", nodes);
  a.put_ints("global_element", elements);
  a.put_ints("block_ranges", std::vector<int>{0, static_cast<int>(elements.size())});
  std::vector<double> u;
  for (int g : nodes)
    for (int k = 0; k < 3; ++k) u.push_back(tag(w, g, k));
  a.put("u", u);
  std::vector<double> stress, state;
  for (int g : elements) {
    for (int k = 0; k < 6; ++k) stress.push_back(tag(w, g, k));
    for (int k = 0; k < state_width; ++k) state.push_back(-tag(w, g, k));
  }
  a.put("block_0_stress", stress);
  if (state_width > 0) a.put("block_0_state", state);
  a.put("energies", std::vector<double>{1.0 + w, 0.5 * (w + 1), 7.0});
  a.put("time", 2.5e-12 * (w + 1));  // a global: only group 0's is kept
  a.put_integer("step", 40);
  return a;
}

RestartLayout layout_for(const std::vector<int>& nodes, const std::vector<int>& elements, int state_width = 0) {
  RestartLayout l;
  l.global_node = nodes;
  l.global_element = elements;
  l.blocks.push_back({0, static_cast<int>(elements.size()), state_width, false});
  l.node_fields = {"u"};
  l.partial_sums = {{"energies", 1}};
  return l;
}

}  // namespace

// Node 2 is held by writers 0 and 1 (with different tags here, so the owner's can be told): the lowest
// holder's value is taken. Node 3 only writer 1 holds.
TEST(RestartRemap, NodeFieldsComeFromTheLowestHolder) {
  const std::vector<StateArchive> groups{writer(0, {0, 1, 2}, {0}), writer(1, {2, 3, 4}, {1})};
  const StateArchive out = remap_restart(groups, layout_for({1, 2, 3}, {}), 0);
  const auto& u = out.array("u");
  ASSERT_EQ(u.size(), 9u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(u[k], tag(0, 1, k));
    EXPECT_EQ(u[3 + k], tag(0, 2, k));
    EXPECT_EQ(u[6 + k], tag(1, 3, k));
  }
  EXPECT_EQ(out.scalar("time"), 2.5e-12);  // group 0's
  EXPECT_EQ(out.integer("node_count"), 3);
  EXPECT_EQ(out.integer("remapped_from_ranks"), 2);
  EXPECT_FALSE(out.has("global_node"));  // the writers' numbering does not travel on
}

// Element records: plain [e][k], and fully integrated blocks' interleaved records (four elements per
// group, element_block.hpp lane_index), each element's values from the writer that held it.
TEST(RestartRemap, ElementRecordsPlainAndInterleaved) {
  const std::vector<StateArchive> groups{writer(0, {0}, {4, 0, 2}, 2), writer(1, {0}, {1, 3}, 2)};
  const StateArchive out = remap_restart(groups, layout_for({0}, {3, 4, 1}, 2), 1);
  const auto& stress = out.array("block_0_stress");
  const auto& state = out.array("block_0_state");
  ASSERT_EQ(stress.size(), 18u);
  const int writer_of[] = {1, 0, 1};
  const int global[] = {3, 4, 1};
  for (int e = 0; e < 3; ++e) {
    for (int k = 0; k < 6; ++k) EXPECT_EQ(stress[6 * e + k], tag(writer_of[e], global[e], k));
    for (int k = 0; k < 2; ++k) EXPECT_EQ(state[2 * e + k], -tag(writer_of[e], global[e], k));
  }

  // Interleaved: writer 0 holds 5 elements (two groups of four, the last padded), the rank takes three.
  const int width = 3;
  StateArchive w0 = writer(0, {0}, {10, 11, 12, 13, 14});
  std::vector<double> records(interleaved_size(5, width), 0.0);
  for (int e = 0; e < 5; ++e)
    for (int k = 0; k < width; ++k) records[lane_index(e, k, width)] = tag(0, 10 + e, k);
  w0.put("block_0_state", records);
  RestartLayout l = layout_for({0}, {14, 10, 13});
  l.blocks[0] = {0, 3, width, true};
  const StateArchive moved = remap_restart({w0}, l, 0);
  const auto& s = moved.array("block_0_state");
  ASSERT_EQ(s.size(), interleaved_size(3, width));
  const int from[] = {14, 10, 13};
  for (int e = 0; e < 3; ++e)
    for (int k = 0; k < width; ++k) EXPECT_EQ(s[lane_index(e, k, width)], tag(0, from[e], k)) << e << " " << k;
}

// Contact arrays are in the contact's numbering (the same rows on every rank): each row from the owner of
// its node; per pass the slave rows' gap, last face and law state (Coulomb's stick flag) likewise; every
// pass searches at the first step (no candidates).
TEST(RestartRemap, ContactRowsAndPassStateComeFromTheOwners) {
  // Surface nodes (global) 1, 3, 4: node 1 owned by writer 0, nodes 3 and 4 by writer 1.
  std::vector<StateArchive> groups{writer(0, {0, 1, 2}, {0}), writer(1, {2, 3, 4}, {1})};
  for (int w = 0; w < 2; ++w) {
    StateArchive& a = groups[w];
    std::vector<double> force, status;
    for (int k = 0; k < 3; ++k) {
      for (int i = 0; i < 3; ++i) force.push_back(tag(w, 100 + k, i));
      status.push_back(w + 0.5);
    }
    a.put("contact_force", force);
    a.put("contact_status", status);
    a.put_integer("contact_passes", 1);
    // The pass's slave nodes are contact rows 0 and 2 (global nodes 1 and 4).
    a.put_ints("contact_pass_0_candidate_offset", std::vector<int>{0, 3, 5});
    a.put_ints("contact_pass_0_candidates", std::vector<int>{1, 2, 3, 4, 5});
    a.put_ints("contact_pass_0_last_face", std::vector<int>{10 * w + 1, 10 * w + 2});
    a.put("contact_pass_0_gap", std::vector<double>{-1e-10 * (w + 1), 2e-10 * (w + 1)});
    a.put("contact_pass_0_law_state", std::vector<double>{w + 0.25, 2.0 + w});
    a.put("contact_pass_0_x_at_search", std::vector<double>(9, 3.0));
    a.put("contact_pass_0_stable_dt", std::vector<double>{1e-13});
    a.put_integer("contact_pass_0_searched", 1);
    a.put_ints("contact_region", std::vector<int>{7, 7, 7});
  }
  RestartLayout l = layout_for({0, 1}, {0});
  l.contact_global_node = {1, 3, 4};
  l.pass_slave_rows = {{0, 2}};
  l.contact_row_fields = {"contact_force", "contact_status"};
  const StateArchive out = remap_restart(groups, l, 0);
  const auto& f = out.array("contact_force");
  const int owner[] = {0, 1, 1};
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) EXPECT_EQ(f[3 * k + i], tag(owner[k], 100 + k, i));
    EXPECT_EQ(out.array("contact_status")[k], owner[k] + 0.5);
  }
  EXPECT_EQ(out.array("contact_pass_0_gap"), (std::vector<double>{-1e-10, 4e-10}));
  EXPECT_EQ(out.integer_array("contact_pass_0_last_face"), (std::vector<long long>{1, 12}));
  EXPECT_EQ(out.array("contact_pass_0_law_state"), (std::vector<double>{0.25, 3.0}));  // row 0 of writer 0, row 1 of writer 1
  EXPECT_EQ(out.integer("contact_pass_0_searched"), 0);
  EXPECT_TRUE(out.integer_array("contact_pass_0_candidates").empty());
  EXPECT_EQ(out.integer_array("contact_pass_0_candidate_offset"), (std::vector<long long>{0, 0, 0}));
  EXPECT_FALSE(out.has("contact_region"));  // a new region at the first search
}

// Node-to-face passes: the candidate lists of the last search move with their slave nodes (each from its
// owner, the rank that searched for it), the positions at that search by node, and `searched` as written,
// so that the next search comes at the step it would have.
TEST(RestartRemap, CandidateListsMoveWithTheirSlaveNodes) {
  std::vector<StateArchive> groups{writer(0, {0, 1, 2}, {0}), writer(1, {2, 3, 4}, {1})};
  for (int w = 0; w < 2; ++w) {
    StateArchive& a = groups[w];
    a.put_integer("contact_passes", 1);
    // Slave rows 0, 2 (global nodes 1, 4), master row 1 (global node 3); writer w's lists: slave 0 has
    // faces {w, 5}, slave 1 has {7 + w}.
    a.put_ints("contact_pass_0_candidate_offset", std::vector<int>{0, 2, 3});
    a.put_ints("contact_pass_0_candidates", std::vector<int>{w, 5, 7 + w});
    a.put_ints("contact_pass_0_last_face", std::vector<int>{-1, -1});
    a.put("contact_pass_0_gap", std::vector<double>{0.0, 0.0});
    std::vector<double> x;
    for (int r = 0; r < 3; ++r)
      for (int i = 0; i < 3; ++i) x.push_back(tag(w, r, i));
    a.put("contact_pass_0_x_at_search", x);
    a.put("contact_pass_0_stable_dt", std::vector<double>{1e-13});
    a.put_integer("contact_pass_0_searched", 1);
  }
  RestartLayout l = layout_for({0, 1}, {0});
  l.contact_global_node = {1, 3, 4};
  l.pass_slave_rows = {{0, 2}};
  l.pass_search_rows = {{0, 2, 1}};  // slave nodes, then master nodes
  l.keep_candidates = true;
  const StateArchive out = remap_restart(groups, l, 1);
  EXPECT_EQ(out.integer_array("contact_pass_0_candidate_offset"), (std::vector<long long>{0, 2, 3}));
  EXPECT_EQ(out.integer_array("contact_pass_0_candidates"), (std::vector<long long>{0, 5, 8}));  // {0, 5} of writer 0, {8} of writer 1
  EXPECT_EQ(out.integer("contact_pass_0_searched"), 1);
  EXPECT_EQ(out.integer("contact_candidates_moved"), 1);
  const auto& x = out.array("contact_pass_0_x_at_search");
  const int owner[] = {0, 1, 1};  // rows 0, 1, 2 of x_at_search: contact rows 0, 2, 1
  for (int r = 0; r < 3; ++r)
    for (int i = 0; i < 3; ++i) EXPECT_EQ(x[3 * r + i], tag(owner[r], r, i));
}

// The partial sums of the save point: the writers' total on rank 0 (in writer order), 0 on the others; the
// other entries of the array from group 0.
TEST(RestartRemap, PartialSumsGoToRankZero) {
  const std::vector<StateArchive> groups{writer(0, {0}, {0}), writer(1, {1}, {1}), writer(2, {2}, {2})};
  const StateArchive zero = remap_restart(groups, layout_for({0}, {0}), 0);
  const StateArchive other = remap_restart(groups, layout_for({1, 2}, {1, 2}), 1);
  EXPECT_EQ(zero.array("energies"), (std::vector<double>{1.0, 0.5 + 1.0 + 1.5, 7.0}));
  EXPECT_EQ(other.array("energies"), (std::vector<double>{1.0, 0.0, 7.0}));
}

TEST(RestartRemap, NodeOrElementOfNoWriterIsBadInput) {
  const std::vector<StateArchive> groups{writer(0, {0, 1}, {0})};
  EXPECT_THROW(remap_restart(groups, layout_for({0, 5}, {0}), 0), SetupError);
  EXPECT_THROW(remap_restart(groups, layout_for({0}, {3}), 0), SetupError);
}

// A rank reads whole only the groups it needs: group 0, the owners of its nodes and contact rows, the
// holders of its elements.
TEST(RestartRemap, OnlyTheNeededGroupsAreRead) {
  const std::vector<StateArchive> ids{writer(0, {0, 1}, {0}), writer(1, {1, 2}, {1}), writer(2, {3}, {2}),
                                      writer(3, {4}, {3})};
  RestartLayout l = layout_for({1, 2}, {1});
  EXPECT_EQ(needs_group(ids, l), (std::vector<char>{1, 1, 0, 0}));
  l.contact_global_node = {4};
  EXPECT_EQ(needs_group(ids, l), (std::vector<char>{1, 1, 0, 1}));
}

// Through the HDF5 file: a one-rank file read as rank 1 of 2 is remapped; the same file without global
// numbers (an earlier tribex) is refused naming the rank count to use; the same rank count reads its own
// group bitwise.
TEST(RestartRemap, FileOfAnotherRankCount) {
  const auto dir = std::filesystem::temp_directory_path() / "tribex_restart_remap";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string with_ids = (dir / "with_ids.h5").string(), without = (dir / "without.h5").string();
  const StateArchive written = writer(0, {0, 1, 2, 3}, {0, 1});
  write_restart_file(with_ids, written);
  StateArchive old = written;
  for (const char* id : {"global_node", "global_element", "block_ranges"}) old.integers.erase(id);
  write_restart_file(without, old);

  const StateArchive out = read_restart_for(with_ids, layout_for({2, 3}, {1}), 1, 2);
  EXPECT_EQ(out.array("u"), (std::vector<double>{tag(0, 2, 0), tag(0, 2, 1), tag(0, 2, 2), tag(0, 3, 0), tag(0, 3, 1),
                                                 tag(0, 3, 2)}));
  EXPECT_EQ(out.array("energies")[1], 0.0);  // rank 1: the writer's partial sum is rank 0's
  const StateArchive same = read_restart_for(with_ids, layout_for({2, 3}, {1}), 0, 1);
  EXPECT_EQ(same.reals, written.reals);
  try {
    read_restart_for(without, layout_for({2, 3}, {1}), 1, 2);
    FAIL() << "a file without global numbers was remapped";
  } catch (const SetupError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("written by 1 rank(s), this run has 2"), std::string::npos) << what;
    EXPECT_NE(what.find("restart with mpirun -np 1"), std::string::npos) << what;
  }
}
