// SPDX-License-Identifier: MIT
// solver/restart/isolated_read.hpp: the restart reader in a child process hands back the archive
// exactly, keeps a SetupError's message, and turns a crash of the reader into a SetupError that names
// the file (issue 54: a crafted restart file made libhdf5 overflow a heap buffer).
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <cstring>

#include "solver/errors.hpp"
#include "solver/restart/isolated_read.hpp"

namespace tribex::solver {
namespace {

TEST(IsolatedRead, ArchiveComesBackBitwise) {
  StateArchive written;
  written.put("u", std::vector<double>{1.0, -0.0, 1e-300, 6.02e23, 0.1});
  written.put("time", 2.5e-11);
  written.put("empty", std::vector<double>{});
  written.put_integers("stable_elements", {3, -7, 1LL << 40});
  const StateArchive read = read_isolated("r.h5", [&] { return written; });
  ASSERT_EQ(read.reals.size(), 3u);
  ASSERT_EQ(read.integers.size(), 1u);
  for (const auto& [name, values] : written.reals) {
    const auto& got = read.array(name);
    ASSERT_EQ(got.size(), values.size()) << name;
    for (std::size_t k = 0; k < values.size(); ++k)
      EXPECT_EQ(std::memcmp(&got[k], &values[k], sizeof(double)), 0) << name << "[" << k << "]";
  }
  EXPECT_EQ(read.integer_array("stable_elements"), written.integers.at("stable_elements"));
}

TEST(IsolatedRead, SetupErrorKeepsItsMessage) {
  try {
    read_isolated("r.h5", []() -> StateArchive { throw SetupError("r.h5: error: restart file lacks 'u'"); });
    FAIL() << "no error";
  } catch (const SetupError& e) {
    EXPECT_STREQ(e.what(), "r.h5: error: restart file lacks 'u'");
  }
}

TEST(IsolatedRead, CrashOfTheReaderIsADamagedFile) {
  for (int sig : {SIGSEGV, SIGABRT}) {
    try {
      read_isolated("damaged.h5", [sig]() -> StateArchive {
        std::signal(sig, SIG_DFL);
        std::raise(sig);
        return {};
      });
      FAIL() << "no error for signal " << sig;
    } catch (const SetupError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("damaged.h5: error: restart file is damaged"), std::string::npos) << m;
      EXPECT_NE(m.find("signal " + std::to_string(sig)), std::string::npos) << m;
    }
  }
  // A sanitizer's report ends the child with an exit status, not a signal.
  EXPECT_THROW(read_isolated("damaged.h5", []() -> StateArchive { std::_Exit(1); }), SetupError);
}

}  // namespace
}  // namespace tribex::solver
