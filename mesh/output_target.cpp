// SPDX-License-Identifier: MIT
#include "mesh/output_target.hpp"

#include <sys/stat.h>

#include "mesh/mesh_error.hpp"

namespace tribex::mesh {

const char* const output_target_fix =
    "; tribex writes only regular files and never replaces anything else: give the path of a new or regular file";

std::string output_target_problem(const std::string& path) {
  struct stat st{};
  if (lstat(path.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return "";
  const char* kind = S_ISFIFO(st.st_mode)  ? "a FIFO (named pipe)"
                     : S_ISCHR(st.st_mode) ? "a character device"
                     : S_ISBLK(st.st_mode) ? "a block device"
                     : S_ISDIR(st.st_mode) ? "a folder"
                     : S_ISLNK(st.st_mode) ? "a symbolic link"
                     : S_ISSOCK(st.st_mode) ? "a socket"
                                            : "not a regular file";
  return path + " is " + kind + ", not a regular file";
}

void require_output_target(const std::string& path) {
  const std::string problem = output_target_problem(path);
  if (!problem.empty()) throw MeshError(problem + output_target_fix);
}

}  // namespace tribex::mesh
