// SPDX-License-Identifier: MIT
#include "solver/restart/isolated_read.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace tribex::solver {
namespace {

// The message through the pipe: one tag byte, then for 'A' (an archive) the reals and the integers
// as (count, then per entry: name length, name, value count, values); for 'E' (a SetupError) and
// 'X' (another exception) the message's length and bytes. Native byte order: both ends are this binary.
class PipeWriter {
 public:
  explicit PipeWriter(int fd) : fd_(fd) {}
  bool bytes(const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    while (n > 0) {
      const ssize_t w = ::write(fd_, c, n);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) return false;
      c += w;
      n -= static_cast<std::size_t>(w);
    }
    return true;
  }
  bool count(std::uint64_t n) { return bytes(&n, sizeof n); }
  bool text(const std::string& s) { return count(s.size()) && bytes(s.data(), s.size()); }
  template <class Map>
  bool arrays(const Map& m) {
    if (!count(m.size())) return false;
    for (const auto& [name, values] : m)
      if (!text(name) || !count(values.size()) || !bytes(values.data(), values.size() * sizeof(values[0]))) return false;
    return true;
  }

 private:
  int fd_;
};

class PipeReader {
 public:
  explicit PipeReader(std::vector<char> data) : data_(std::move(data)) {}
  void bytes(void* p, std::size_t n) {
    if (n > data_.size() - at_) throw std::length_error("short");
    if (n == 0) return;  // an empty array's data() may be null, and memcpy's arguments may not
    std::memcpy(p, data_.data() + at_, n);
    at_ += n;
  }
  std::uint64_t count() {
    std::uint64_t n = 0;
    bytes(&n, sizeof n);
    return n;
  }
  std::string text() {
    std::string s(checked(count(), 1), '\0');
    bytes(s.data(), s.size());
    return s;
  }
  template <class Map>
  void arrays(Map& m) {
    for (std::uint64_t k = count(); k > 0; --k) {
      const std::string name = text();
      auto& values = m[name];
      values.resize(checked(count(), sizeof(values[0])));
      bytes(values.data(), values.size() * sizeof(values[0]));
    }
  }
  bool done() const { return at_ == data_.size(); }

 private:
  // A count cannot exceed what is left of the message (no allocation from a garbled count).
  std::size_t checked(std::uint64_t n, std::size_t item) const {
    if (n > (data_.size() - at_) / item) throw std::length_error("short");
    return static_cast<std::size_t>(n);
  }
  std::vector<char> data_;
  std::size_t at_ = 0;
};

[[noreturn]] void child(int fd, const std::function<StateArchive()>& read, unsigned seconds) {
  std::signal(SIGALRM, SIG_DFL);
  ::alarm(seconds);  // a reader that spins in a damaged file ends (every loop bounded)
  PipeWriter out(fd);
  bool sent = false;
  try {
    const StateArchive a = read();
    sent = out.bytes("A", 1) && out.arrays(a.reals) && out.arrays(a.integers);
  } catch (const SetupError& e) {
    sent = out.bytes("E", 1) && out.text(e.what());
  } catch (const std::exception& e) {
    sent = out.bytes("X", 1) && out.text(e.what());
  }
  ::close(fd);
  _exit(sent ? 0 : 4);  // _exit: no atexit handlers, no flush of the stdio buffers copied from the run
}

std::vector<char> read_all(int fd) {
  std::vector<char> data;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t r = ::read(fd, buffer, sizeof buffer);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    data.insert(data.end(), buffer, buffer + r);
  }
  return data;
}

std::string how_it_ended(int status) {
  if (WIFSIGNALED(status)) {
    const char* name = strsignal(WTERMSIG(status));
    return "signal " + std::to_string(WTERMSIG(status)) + (name ? std::string(", ") + name : "");
  }
  return "exit status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

}  // namespace

StateArchive read_isolated(const std::string& path, const std::function<StateArchive()>& read) {
  // The reader's time limit: 60 s plus 1 s per 10 MB of file (restart files read at over 100 MB/s).
  std::error_code size_error;
  const auto bytes = std::filesystem::file_size(path, size_error);
  const unsigned seconds = 60 + static_cast<unsigned>(size_error ? 0 : std::min<std::uintmax_t>(bytes / 10'000'000, 86'400));
  int fds[2];
  if (::pipe(fds) != 0) throw SetupError(path + ": error: cannot read the restart file (no pipe: " + std::strerror(errno) + ")");
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw SetupError(path + ": error: cannot read the restart file (fork: " + std::strerror(errno) + ")");
  }
  if (pid == 0) {
    ::close(fds[0]);
    child(fds[1], read, seconds);
  }
  ::close(fds[1]);
  std::vector<char> data = read_all(fds[0]);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const std::string damaged = path + ": error: restart file is damaged: reading it ";
  const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM)
    throw SetupError(damaged + "did not finish within " + std::to_string(seconds) +
                     " s (a damaged HDF5 structure the library walks without end); restart from a file a tribex run wrote");
  if (!clean || data.empty())
    throw SetupError(damaged + "crashed the HDF5 reader (" + how_it_ended(status) +
                     "); restart from another restart_<k>.h5 of the ring or a file a tribex run wrote");
  PipeReader in(std::move(data));
  try {
    char tag = 0;
    in.bytes(&tag, 1);
    if (tag == 'E') throw SetupError(in.text());
    if (tag == 'X') throw std::runtime_error(in.text());
    StateArchive a;
    in.arrays(a.reals);
    in.arrays(a.integers);
    if (tag == 'A' && in.done()) return a;
  } catch (const std::length_error&) {
  }
  throw SetupError(damaged + "gave a garbled archive; restart from a file a tribex run wrote");
}

}  // namespace tribex::solver
