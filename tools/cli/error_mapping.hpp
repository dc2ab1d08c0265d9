// SPDX-License-Identifier: MIT
// One place that maps the error types of every layer onto exit codes and prints them once.
#pragma once

#include <cstdio>
#include <exception>
#include <string>

#include "inputs/diagnostics.hpp"
#include "mesh/mesh_error.hpp"
#include "solver/errors.hpp"
#include "solver/run/stop_signal.hpp"
#include "tools/common/errors.hpp"

namespace tribex::cli {

/// Runs `body`, printing each error once to `err` (stderr; in a parallel run a buffer that the
/// front end prints from the one rank that failed first).
template <class F>
int run_mapping_errors(F&& body, std::FILE* err = stderr) {
  try {
    return body();
  } catch (const solver::StoppedByOtherRank& e) {
    return e.exit_code;  // the rank that failed prints the message
  } catch (const inputs::DeckError& e) {
    for (const auto& d : e.diagnostics()) std::fprintf(err, "%s\n", d.str().c_str());
    std::fprintf(err, "tribex: %zu error(s) in the deck; nothing was run\n", e.diagnostics().size());
    return tools::exit_bad_input;
  } catch (const tools::BadInput& e) {
    std::fprintf(err, "error: %s\n", e.what());
    return tools::exit_bad_input;
  } catch (const mesh::MeshError& e) {
    std::fprintf(err, "error: %s\n", e.what());
    return tools::exit_bad_input;
  } catch (const solver::SetupError& e) {
    // Messages that point at a deck line already read "FILE:LINE:COL: error: ...".
    const bool located = std::string(e.what()).find(": error: ") != std::string::npos;
    std::fprintf(err, "%s%s\n", located ? "" : "error: ", e.what());
    return tools::exit_bad_input;
  } catch (const solver::Interrupted& e) {
    std::fprintf(err, "%s\n", e.what());
    return tools::exit_interrupted;
  } catch (const solver::OutputError& e) {
    std::fprintf(err, "Error termination: output failure: %s\n", e.what());
    return tools::exit_numerical_failure;
  } catch (const solver::NumericalFailure& e) {
    std::fprintf(err, "Error termination: numerical failure: %s\n", e.what());
    return tools::exit_numerical_failure;
  } catch (const std::exception& e) {
    std::fprintf(err, "tribex: internal error: %s (please report it)\n", e.what());
    return tools::exit_internal_error;
  }
}

}  // namespace tribex::cli
