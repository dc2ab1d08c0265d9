// SPDX-License-Identifier: MIT
// The tools' JSON pieces are the solver's (solver/output/json.hpp: one implementation, in the lower
// layer, shared with summary.json).
#pragma once

#include "solver/output/json.hpp"

namespace tribex::tools {

using solver::json_number;
using solver::json_string;

}  // namespace tribex::tools
