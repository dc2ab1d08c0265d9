// SPDX-License-Identifier: MIT
// Test support: a `tribex` subcommand run as the front end runs it (every error mapped to its exit
// code by tools/cli/error_mapping.hpp), with what it printed to stderr, for the CLI tests of the tools.
#pragma once

#include <cstdio>
#include <string>
#include <utility>

#include "tools/cli/error_mapping.hpp"

namespace tribex::test {

template <class Command>
std::pair<int, std::string> run_capturing_stderr(Command command) {
  std::FILE* err = std::tmpfile();
  const int code = cli::run_mapping_errors(command, err);
  std::rewind(err);
  std::string text;
  char buf[512];
  while (std::fgets(buf, sizeof buf, err)) text += buf;
  std::fclose(err);
  return {code, text};
}

}  // namespace tribex::test
