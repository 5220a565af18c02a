#include "importers/mesh/off_header.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>

#include "core/error.h"

namespace viscera::importers {
namespace {

/// Bytes read from the start of the file: the header and any comment lines before it.
constexpr std::size_t kHeaderWindow = std::size_t{1} << 20;

/// A decimal count as written, and its value if it fits assimp's unsigned 32-bit counter.
struct Count {
  std::string digits;
  std::uint64_t value = 0;
  bool fits = true;
};

bool is_space_or_line_end(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// assimp's NextToken of the OFF reader: blanks, line ends and whole lines starting with '#'.
std::size_t next_token(std::string_view text, std::size_t at) {
  const auto skip_blanks = [&] {
    while (at < text.size() && is_space_or_line_end(text[at]))
      ++at;
  };
  skip_blanks();
  while (at < text.size() && text[at] == '#') {
    while (at < text.size() && text[at] != '\n' && text[at] != '\r')
      ++at;
    skip_blanks();
  }
  return at;
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

/// The digits at `at` (none gives 0, as assimp's strtoul10 does); `at` moves past them.
Count read_count(std::string_view text, std::size_t& at) {
  Count count;
  constexpr std::uint64_t kLimit = std::numeric_limits<std::uint32_t>::max();
  while (at < text.size() && is_digit(text[at])) {
    count.digits += text[at];
    count.value = std::min<std::uint64_t>(count.value * 10 + static_cast<unsigned>(text[at] - '0'),
                                          kLimit + 1);
    ++at;
  }
  count.fits = count.value <= kLimit;
  return count;
}

std::string line_of(std::string_view text, std::size_t at) {
  return "line " + std::to_string(1 + std::count(text.begin(), text.begin() + at, '\n'));
}

}  // namespace

void check_off_counts(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return;  // assimp reports a file it cannot open
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(std::min<std::uintmax_t>(size, kHeaderWindow)), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));

  // The keyword's prefixes in assimp's order; only "n" (a dimension follows) matters here.
  std::size_t at = next_token(text, 0);
  const auto take = [&](std::string_view word) {
    if (text.compare(at, word.size(), word) != 0) return false;
    at += word.size();
    return true;
  };
  take("ST");
  take("C");
  take("N");
  take("4");
  const bool has_dimension = take("n");
  if (take("OFF")) {
    at = next_token(text, at);
  } else {
    // No keyword, which the format allows: assimp then wants a count here.
    at = next_token(text, at);
    if (at >= text.size() || !is_digit(text[at])) return;
  }
  if (has_dimension) {
    const Count dimension = read_count(text, at);
    if (dimension.fits && dimension.value > 3) return;  // assimp refuses it
    at = next_token(text, at);
  }
  at = next_token(text, at);
  const std::string where = line_of(text, at);
  const Count vertices = read_count(text, at);
  at = next_token(text, at);
  const Count faces = read_count(text, at);
  for (const Count* count : {&vertices, &faces}) {
    if (!count->fits) {
      throw core::InputError("the OFF header declares " + count->digits + " " +
                                 (count == &vertices ? "vertices" : "faces") +
                                 ", more than a 32-bit count holds (4294967295)",
                             {file, "", where});
    }
  }
  if (vertices.value == 0 || faces.value == 0) return;  // assimp refuses it
  const std::uint64_t needed = 2 * (vertices.value + faces.value) - 1;
  const std::uint64_t follow = size - at;
  if (needed > follow) {
    throw core::InputError("the OFF header declares " + vertices.digits + " vertices and " +
                               faces.digits + " faces, a line each: at least " +
                               std::to_string(needed) + " bytes, but only " +
                               std::to_string(follow) + " follow the header",
                           {file, "", where});
  }
}

}  // namespace viscera::importers
