// SPDX-License-Identifier: MIT
// SHA-256 (FIPS 180-4, section 6.2) of a byte string or a file, as 64 lower-case hex digits: the
// identity of a deck in log.txt and summary.json (and of the inputs a restart file was written with).
#pragma once

#include <string>
#include <string_view>

namespace tribex::inputs {

std::string sha256_hex(std::string_view bytes);
/// The file's SHA-256; throws std::runtime_error naming the file when it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace tribex::inputs
