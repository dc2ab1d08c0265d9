// SPDX-License-Identifier: MIT
// Set-up data as plain bytes for MPI messages (parallel/mesh_part.cpp, contact_setup.cpp): counts as
// 64-bit integers, then the values; both sides are the same build on the same kind of machine.
#pragma once

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace tribex::solver::parallel {

class ByteWriter {
 public:
  template <class T>
  void values(const std::vector<T>& v) {
    count(v.size());
    append(v.data(), v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    count(s.size());
    append(s.data(), s.size());
  }
  void count(std::size_t n) {
    const long long c = static_cast<long long>(n);
    append(&c, sizeof c);
  }
  std::vector<char> bytes;

 private:
  void append(const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    bytes.insert(bytes.end(), c, c + n);
  }
};

class ByteReader {
 public:
  explicit ByteReader(const std::vector<char>& b) : bytes_(b) {}
  template <class T>
  std::vector<T> values() {
    std::vector<T> v(count());
    take(v.data(), v.size() * sizeof(T));
    return v;
  }
  std::string text() {
    std::string s(count(), '\0');
    take(s.data(), s.size());
    return s;
  }
  std::size_t count() {
    long long c = 0;
    take(&c, sizeof c);
    return static_cast<std::size_t>(c);
  }

 private:
  void take(void* p, std::size_t n) {
    if (at_ + n > bytes_.size()) throw std::logic_error("set-up message shorter than its contents");
    if (n) std::memcpy(p, bytes_.data() + at_, n);
    at_ += n;
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

/// Collective: `bytes` of `root` on every rank (in pieces under 1 GiB).
void broadcast_bytes(std::vector<char>& bytes, int root = 0);

}  // namespace tribex::solver::parallel
