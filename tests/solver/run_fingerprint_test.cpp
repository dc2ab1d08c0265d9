// SPDX-License-Identifier: MIT
// restart_difference: a restart file from a tribex that lacked a key, now written at its default in the
// resolved deck, resumes (the run is the same); the same key at another value, or any other change, does not.
#include <gtest/gtest.h>

#include "solver/restart/run_fingerprint.hpp"

namespace tribex::solver {
namespace {

StateArchive written_by(const std::string& deck_text) {
  StateArchive a;
  a.put_integers("deck_text", as_codes(deck_text));
  a.put_integers("mesh_sha256", as_codes("abc"));
  return a;
}

const std::string then_text =
    "begin sierra s\n  begin presto procedure p\n    begin time control\n      termination time = 1e-09 s\n"
    "      time step scale factor = 0.9\n    end time control\n  end presto procedure p\nend sierra s\n";

std::string with_line(const std::string& line) {
  std::string t = then_text;
  const std::string anchor = "    end time control\n";
  return t.insert(t.find(anchor), line);
}

TEST(RestartDifference, AKeyAddedSinceAtItsDefaultIsTheSameRun) {
  EXPECT_EQ(restart_difference(written_by(then_text), then_text, "abc"), "");
  EXPECT_EQ(restart_difference(written_by(then_text), with_line("      viscous dissipation = half step\n"), "abc"), "");
}

TEST(RestartDifference, AnAddedKeyAtAnotherValueOrAnotherChangeIsNamed) {
  EXPECT_EQ(restart_difference(written_by(then_text), with_line("      viscous dissipation = exact\n"), "abc"),
            "the resolved deck differs at its line 6: '    end time control' then, '      viscous dissipation = exact' now");
  // a key that is not the block's, even at a value that is another block's default
  EXPECT_NE(restart_difference(written_by(then_text), with_line("      mass damping coefficient = 0\n"), "abc"), "");
  std::string longer = then_text;
  longer.replace(longer.find("1e-09"), 5, "2e-09");
  EXPECT_NE(restart_difference(written_by(then_text), longer, "abc").find("line 4"), std::string::npos);
  EXPECT_EQ(restart_difference(written_by(then_text), then_text, "abd"), "the mesh differs (coordinates or connectivity)");
}

}  // namespace
}  // namespace tribex::solver
