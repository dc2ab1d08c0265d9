// SPDX-License-Identifier: MIT
#include "solver/errors.hpp"

#include <cstring>

namespace tribex::solver {

OutputError output_failure(const std::string& path, int error_number) {
  const std::string reason = error_number ? std::strerror(error_number) : "write failed";
  return OutputError(reason + " while writing " + path +
                     "; free space on the device or choose another output folder (-o); the files up to the last "
                     "complete output step are kept");
}

}  // namespace tribex::solver
