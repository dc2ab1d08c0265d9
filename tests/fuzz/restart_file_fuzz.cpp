// SPDX-License-Identifier: MIT
// libFuzzer target for restart files (issue 54, items 9, 11, 17): any bytes, written to a scratch file,
// must give an archive whose values pass check_restart_values, or a SetupError naming the file, from
// read_restart_file (HDF5, in a child process as a run reads it: solver/restart/isolated_read.hpp)
// and the checks; never a crash, a hang, an allocation beyond what the file holds or another
// exception. A crash inside libhdf5 ends the child only (its sanitizer report still goes to stderr). Built only with -DTRIBEX_FUZZ=ON (clang); tests/fuzz/CMakeLists.txt.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "tests/fuzz/skip_library_teardown.hpp"
#include "inputs/deck.hpp"
#include "solver/errors.hpp"
#include "solver/restart/isolated_read.hpp"
#include "solver/restart/restart_checks.hpp"
#include "solver/restart/restart_remap.hpp"
#include "solver/restart/state_archive.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = "restart_fuzz_" + std::to_string(getpid()) + ".h5";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  tribex::inputs::TimeControlSpec tc;  // the span of tests/parallel/mpi_wave.i, whose files are the seeds
  tc.termination_time = 2e-11;
  try {
    const tribex::solver::StateArchive a = tribex::solver::read_isolated(path, [] { return tribex::solver::read_restart_file(path); });
    tribex::solver::check_restart_values(a, tc, true, path);
    // What restore_state reads first: typed accessors on the archive.
    if (a.has("u")) (void)a.array("u");
    if (a.has("stable_elements")) (void)a.integer_array("stable_elements");
  } catch (const tribex::solver::SetupError&) {
    // expected for almost every input
  }
  // The same bytes resumed on another rank count (issue 57): rank 0 of 2 with a one-element layout reads
  // the groups it needs and moves their arrays by global number (solver/restart/restart_remap.hpp).
  try {
    static const tribex::solver::RestartLayout layout = [] {
      tribex::solver::RestartLayout l;
      for (int n = 0; n < 8; ++n) l.global_node.push_back(n);
      l.global_element = {0};
      l.blocks.push_back({0, 1, 0, false});
      l.node_fields = {"u", "v_half", "v_prev_half", "v_n", "acceleration", "force", "reaction"};
      l.reformed_node_fields = {"external_force"};
      l.partial_sums = {{"energies", 1}, {"lagged_power", 1}, {"material_work", 0}};
      return l;
    }();
    (void)tribex::solver::read_isolated(path, [] { return tribex::solver::read_restart_for(path, layout, 0, 2); });
  } catch (const tribex::solver::SetupError&) {
  }
  return 0;
}
