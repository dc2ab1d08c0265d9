// SPDX-License-Identifier: MIT
// A writer's state after a crash (tests/output): `work` runs in a forked child that then ends with
// _exit(0), so no destructor runs and no file is closed, as when a run is killed after that point.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

namespace tribex::test {

/// True when the child ran `work` to its end and exited 0 (false: fork failed or `work` crashed).
template <class Work>
bool ran_in_child_left_unclosed(Work work) {
  const pid_t child = fork();
  if (child < 0) return false;
  if (child == 0) {
    work();
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

}  // namespace tribex::test
