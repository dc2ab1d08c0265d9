// SPDX-License-Identifier: MIT
// What a subcommand's file (tools/*/..._command.cpp) works with, in one using-directive:
//
//   namespace tribex::gw { namespace { using namespace tools::command; ... } }
//
// the argument parser (Args), the bad-input error (BadInput: exit code 2) and the unit dimensions that
// Args::real and the tables take (dim::length, dim::pressure, ...).
#pragma once

#include "inputs/units.hpp"
#include "tools/common/args.hpp"
#include "tools/common/errors.hpp"

namespace tribex::tools::command {

using tools::Args;
using tools::BadInput;
namespace dim = inputs::dim;

}  // namespace tribex::tools::command
