// SPDX-License-Identifier: MIT
// The subcommands of `tribex`; each takes the arguments after its name and returns an exit code.
// Errors are thrown, not returned: run_mapping_errors() turns them into exit codes.
#pragma once

#include <string>
#include <vector>

namespace tribex::cli {

int run_command(const std::vector<std::string>& args);    // tools/cli/run_command.cpp
int check_command(const std::vector<std::string>& args);  // tools/cli/run_command.cpp
int keys_command(const std::vector<std::string>& args);   // tools/cli/keys_command.cpp
int bench_command(const std::vector<std::string>& args);  // tools/bench/bench_command.cpp
int plot_command(const std::vector<std::string>& args);   // tools/cli/plot_command.cpp: tribex plot history OUT

int gw_command(const std::vector<std::string>& args);       // tools/gw/gw_command.cpp
int surface_command(const std::vector<std::string>& args);  // tools/surface/surface_command.cpp
int pstd_command(const std::vector<std::string>& args);  // tools/pstd/
/// tools/friction_test/command.cpp: `tribex friction-test calibrate|static|dynamic|synth`.
int friction_test_command(const std::vector<std::string>& args);
/// tools/fit/fit_command.cpp: `tribex fit friction|synth`.
int fit_command(const std::vector<std::string>& args);
/// tools/mesh/mesh_command.cpp: `tribex mesh afm FILE ... -o MESH.msh`.
int mesh_command(const std::vector<std::string>& args);
/// tools/join/join_command.cpp: `tribex join OUT`: a parallel run's results.exo.N.r joined into results.exo.
int join_command(const std::vector<std::string>& args);
/// tools/layered/layered_command.cpp: `tribex layered`: sphere on bonded elastic layers (Hankel-space kernel).
int layered_command(const std::vector<std::string>& args);
/// tools/adhesion/adhesion_command.cpp: `tribex adhesion-curve`: Lennard-Jones sphere-flat reference (both branches).
int adhesion_curve_command(const std::vector<std::string>& args);

}  // namespace tribex::cli
