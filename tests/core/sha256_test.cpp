// SHA-256 (core/sha256.h) against the FIPS 180-4 examples, fed whole and in pieces that cross
// the 64-byte block, and with the empty spans a world without nodes hashes (an empty vector's
// data() may be null: the sanitizer run's UrethraSession finding).
#include "core/sha256.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace viscera::core {
namespace {

constexpr const char* kTwoBlocks = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";

TEST(Sha256, matches_the_fips_180_examples) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex(kTwoBlocks),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, pieces_that_cross_a_block_give_the_digest_of_the_whole) {
  const std::string text = std::string(kTwoBlocks) + kTwoBlocks + kTwoBlocks;  // 168 bytes
  for (const std::size_t cut : {1u, 55u, 63u, 64u, 65u, 100u, 167u}) {
    Sha256 pieces;
    pieces.update(std::string_view(text).substr(0, cut));
    pieces.update(std::string_view(text).substr(cut));
    EXPECT_EQ(pieces.hex_digest(), sha256_hex(text)) << "cut at " << cut;
  }
}

TEST(Sha256, an_empty_span_changes_nothing) {
  const std::vector<double> none;
  Sha256 hash;
  hash.update(std::as_bytes(std::span<const double>(none)));
  hash.update("abc");
  hash.update(std::as_bytes(std::span<const double>(none)));
  EXPECT_EQ(hash.hex_digest(), sha256_hex("abc"));
}

}  // namespace
}  // namespace viscera::core
