// SPDX-License-Identifier: MIT
// The output folder's lock: one run at a time writes into a folder (README.md "The output folder").
#pragma once

#include <filesystem>
#include <string>

namespace tribex::solver {

/// Holds OUT/.tribex_lock for the life of the object with flock(2) (exclusive, non-blocking): the
/// kernel drops the lock when the process ends in any way, so a crashed run's lock file is stale,
/// found free, and taken over. The file holds the holder's pid, host, start time and run id, so a
/// refused run can name it. Released by unlinking the file while it is still locked (a run that
/// opened the old file checks after locking that it still is the file under that name, and retries).
class OutputLock {
 public:
  /// Takes the lock of the existing folder `folder`; SetupError naming the live holder (pid, host,
  /// start, run id) if another process holds it. `holder` is the text written into the lock file.
  OutputLock(const std::filesystem::path& folder, const std::string& holder);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  /// The earlier holder's text when its lock was stale (a run that ended without releasing it), else "".
  const std::string& stale_holder() const { return stale_; }
  static constexpr const char* file_name = ".tribex_lock";

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::string stale_;
};

/// "pid 1234 on host NAME, started 2026-...Z, run RUNID": the lock file's text for this process.
std::string lock_holder_text(const std::string& host, const std::string& started_utc, const std::string& run_id);

}  // namespace tribex::solver
