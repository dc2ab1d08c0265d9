// SPDX-License-Identifier: MIT
// SHA-256 against the FIPS 180-2 appendix B examples and NIST's empty-message value.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "inputs/sha256.hpp"

using tribex::inputs::sha256_file;
using tribex::inputs::sha256_hex;

TEST(Sha256, FipsExamples) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // Two blocks after padding (56 bytes: the length no longer fits in the first block).
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  EXPECT_EQ(sha256_hex(std::string(1000000, 'a')), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST(Sha256, FileEqualsBytesAndMissingFileThrows) {
  const auto path = std::filesystem::temp_directory_path() / "tribex_sha256_test.txt";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  std::fputs("abc", f);
  std::fclose(f);
  EXPECT_EQ(sha256_file(path.string()), sha256_hex("abc"));
  std::filesystem::remove(path);
  EXPECT_THROW(sha256_file(path.string()), std::runtime_error);
}

TEST(Sha256, IncrementalEqualsOneStringAtEveryChunkSize) {
  // The FIPS two-block message and a million 'a' fed in pieces of 1 to 200 bytes: the same digests.
  const std::string two_blocks = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
  for (std::size_t piece : {1u, 3u, 55u, 56u, 63u, 64u, 65u, 200u}) {
    tribex::inputs::Sha256 hash;
    for (std::size_t at = 0; at < two_blocks.size(); at += piece) hash.update(std::string_view(two_blocks).substr(at, piece));
    EXPECT_EQ(hash.hex(), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1") << piece;
  }
  const std::string million(1000000, 'a');
  tribex::inputs::Sha256 hash;
  for (std::size_t at = 0; at < million.size(); at += 4099) hash.update(std::string_view(million).substr(at, 4099));
  EXPECT_EQ(hash.hex(), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}
