// SPDX-License-Identifier: MIT
// SHA-256 (FIPS 180-4, section 6.2) of a byte string or a file, as 64 lower-case hex digits: the
// identity of a deck in log.txt and summary.json (and of the inputs a restart file was written with).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace tribex::inputs {

/// Incremental SHA-256: the bytes given to update, in order, as if one string (no copy of them).
class Sha256 {
 public:
  Sha256& update(std::string_view bytes);
  /// The digest as 64 hex digits (the hasher is spent afterwards).
  std::string hex();

 private:
  std::array<std::uint32_t, 8> H_ = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                     0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};  // section 5.3.3
  unsigned char pending_[64] = {};
  std::size_t pending_size_ = 0;
  std::uint64_t length_ = 0;  // bytes
};

std::string sha256_hex(std::string_view bytes);
/// The file's SHA-256; throws std::runtime_error naming the file when it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace tribex::inputs
