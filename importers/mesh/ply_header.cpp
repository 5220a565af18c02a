#include "importers/mesh/ply_header.h"

#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"

namespace viscera::importers {
namespace {

/// Characters of a header line kept: enough for its keywords, whatever follows.
constexpr std::size_t kLineKeep = 4096;
constexpr std::uint64_t kMaxCount = std::numeric_limits<std::uint32_t>::max();

/// One "element NAME COUNT" line and the least bytes one of its instances takes.
struct Element {
  std::string name, digits;
  std::uint64_t count = 0;
  std::uint64_t least_bytes = 0;
};

/// Bytes of a binary scalar of a PLY type name (both spellings); 0 when unknown.
std::uint64_t type_size(const std::string& type) {
  static const std::map<std::string, std::uint64_t> sizes = {
      {"char", 1},   {"int8", 1},    {"uchar", 1},  {"uint8", 1},  {"short", 2}, {"int16", 2},
      {"ushort", 2}, {"uint16", 2},  {"int", 4},    {"int32", 4},  {"uint", 4},  {"uint32", 4},
      {"float", 4},  {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto found = sizes.find(type);
  return found == sizes.end() ? 0 : found->second;
}

/// Reads one line into `line` (its first kLineKeep characters, without the line end); false at
/// the end of the file. `offset` counts the bytes consumed.
bool next_line(std::streambuf& bytes, std::string& line, std::uint64_t& offset) {
  line.clear();
  bool any = false;
  for (int c = bytes.sbumpc(); c != std::char_traits<char>::eof(); c = bytes.sbumpc()) {
    any = true;
    ++offset;
    if (c == '\n') break;
    if (line.size() < kLineKeep && c != '\r') line += static_cast<char>(c);
  }
  return any;
}

std::vector<std::string> words_of(const std::string& line) {
  std::istringstream stream(line);
  std::vector<std::string> words;
  for (std::string word; stream >> word;)
    words.push_back(word);
  return words;
}

bool all_digits(const std::string& word) {
  return !word.empty() && word.find_first_not_of("0123456789") == std::string::npos;
}

/// `a` × `b`, or the largest value when that overflows.
std::uint64_t saturating_product(std::uint64_t a, std::uint64_t b) {
  if (b != 0 && a > std::numeric_limits<std::uint64_t>::max() / b)
    return std::numeric_limits<std::uint64_t>::max();
  return a * b;
}

}  // namespace

void check_ply_header(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  if (error || !in) return;  // assimp reports a file it cannot open
  std::streambuf& bytes = *in.rdbuf();
  std::string line;
  std::uint64_t offset = 0;
  // Assimp has chosen its PLY reader for this file (by its extension or its first bytes), so
  // whatever the first line holds — "ply" glued to the next word by a NUL still sends assimp
  // looking for end_header (the mesh_ply target's second finding) — the header must end.
  if (!next_line(bytes, line, offset)) return;  // an empty file: assimp refuses it

  std::string format;
  std::vector<Element> elements;
  bool ended = false;
  int line_number = 1;
  while (!ended && next_line(bytes, line, offset)) {
    ++line_number;
    const auto words = words_of(line);
    if (words.empty()) continue;
    const std::string where = "line " + std::to_string(line_number);
    if (words[0] == "end_header") {
      ended = true;
    } else if (words[0] == "format" && words.size() >= 2) {
      format = words[1];
    } else if (words[0] == "element" && words.size() >= 3 && all_digits(words[2])) {
      Element element{words[1], words[2]};
      element.count = words[2].size() > 10 ? kMaxCount + 1 : std::stoull(words[2]);
      if (element.count > kMaxCount) {
        throw core::InputError("the PLY header declares " + words[2] + " \"" + words[1] +
                                   "\" elements, more than a 32-bit count holds (4294967295)",
                               {file, "", where});
      }
      elements.push_back(element);
    } else if (words[0] == "property" && words.size() >= 2 && !elements.empty()) {
      // A list takes at least its count; a scalar its one value.
      const bool list = words[1] == "list";
      const std::uint64_t binary = type_size(list && words.size() >= 3 ? words[2] : words[1]);
      elements.back().least_bytes += format == "ascii" ? 2 : binary;
    }
  }
  if (!ended) {
    throw core::InputError("the PLY header has no end_header line", {file, "", "header"});
  }
  if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
    return;  // assimp refuses a format it does not know
  std::uint64_t needed = 0;
  std::string declared;
  for (const Element& element : elements) {
    const std::uint64_t part = saturating_product(element.count, element.least_bytes);
    needed = part > std::numeric_limits<std::uint64_t>::max() - needed
                 ? std::numeric_limits<std::uint64_t>::max()
                 : needed + part;
    declared += (declared.empty() ? "" : ", ") + element.digits + " \"" + element.name + "\"";
  }
  // In ASCII the file's last value may end it without a separator.
  if (format == "ascii" && needed > 0) --needed;
  const std::uint64_t follow = size - offset;
  if (needed > follow) {
    throw core::InputError("the PLY header declares elements " + declared + ": at least " +
                               std::to_string(needed) + " bytes in " + format + ", but only " +
                               std::to_string(follow) + " follow end_header",
                           {file, "", "header"});
  }
}

}  // namespace viscera::importers
