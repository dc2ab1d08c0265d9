// SPDX-License-Identifier: MIT
#include "solver/output/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "solver/errors.hpp"

namespace tribex::solver {
namespace {

std::string read_all(int fd) {
  std::string text;
  char buf[512];
  ssize_t n = 0;
  if (lseek(fd, 0, SEEK_SET) < 0) return text;
  while ((n = read(fd, buf, sizeof buf)) > 0 && text.size() < 4096) text.append(buf, static_cast<std::size_t>(n));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text;
}

}  // namespace

std::string lock_holder_text(const std::string& host, const std::string& started_utc, const std::string& run_id) {
  return "pid " + std::to_string(static_cast<long>(getpid())) + " on host " + (host.empty() ? "(unnamed)" : host) +
         ", started " + started_utc + ", run " + run_id;
}

OutputLock::OutputLock(const std::filesystem::path& folder, const std::string& holder)
    : path_(folder / file_name) {
  // A few tries: the file may be unlinked by its releasing holder between our open and our flock.
  for (int attempt = 0; attempt < 20; ++attempt) {
    const int fd = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      throw SetupError("cannot create the lock file " + path_.string() + ": " + std::strerror(errno) +
                       "; choose another output folder (-o) or fix its permissions");
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      std::string other = read_all(fd);
      close(fd);
      if (err != EWOULDBLOCK)
        throw SetupError("cannot lock the output folder " + folder.string() + " (" + std::strerror(err) +
                         "); choose an output folder on a file system with locks (-o)");
      throw SetupError("output folder " + folder.string() + " is in use by another tribex run (" +
                       (other.empty() ? std::string("its pid and host not yet written") : other) +
                       "); wait for it to end, or choose another output folder (-o)");
    }
    struct stat held{}, named{};
    if (fstat(fd, &held) == 0 && stat(path_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      fd_ = fd;
      break;
    }
    close(fd);  // released and unlinked by its holder meanwhile: open the new file
  }
  if (fd_ < 0) throw SetupError("cannot take the lock " + path_.string() + " (it keeps changing); try again");
  stale_ = read_all(fd_);
  const std::string text = holder + "\n";
  if (ftruncate(fd_, 0) != 0 || pwrite(fd_, text.data(), text.size(), 0) != static_cast<ssize_t>(text.size())) {
    const int err = errno;
    unlink(path_.c_str());
    close(fd_);
    fd_ = -1;
    const std::string reason = err == ENOSPC || err == EDQUOT ? no_space_reason(path_.string()) : std::strerror(err);
    throw SetupError("cannot write the lock file " + path_.string() + ": " + reason +
                     "; free space on the device or choose another output folder (-o)");
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  unlink(path_.c_str());  // still locked: a waiting run finds the name gone and opens a new file
  close(fd_);
}

}  // namespace tribex::solver
