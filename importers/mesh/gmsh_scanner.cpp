#include "importers/mesh/gmsh_scanner.h"

#include <cctype>
#include <charconv>

namespace viscera::importers {

std::string_view GmshScanner::line() {
  if (at_end()) truncated();
  const std::size_t end = bytes_.find('\n', position_);
  const std::size_t stop = end == std::string::npos ? bytes_.size() : end;
  std::string_view text(bytes_.data() + position_, stop - position_);
  position_ = end == std::string::npos ? bytes_.size() : end + 1;
  while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t'))
    text.remove_suffix(1);
  return text;
}

std::string_view GmshScanner::next_line() {
  while (true) {
    std::string_view text = line();
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
      text.remove_prefix(1);
    if (!text.empty()) return text;
  }
}

void GmshScanner::expect_line(std::string_view expected) {
  const std::string_view found = next_line();
  if (found != expected) {
    std::string shown(found.substr(0, 40));
    fail("expected \"" + std::string(expected) + "\" but found \"" + shown + "\"");
  }
}

void GmshScanner::skip_past(std::string_view end) {
  while (true) {
    if (at_end()) fail("the file ends before \"" + std::string(end) + "\"");
    if (line() == end) return;
  }
}

std::string_view GmshScanner::token() {
  while (position_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[position_])))
    ++position_;
  if (at_end()) truncated();
  const std::size_t start = position_;
  while (position_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[position_])))
    ++position_;
  return std::string_view(bytes_.data() + start, position_ - start);
}

std::int64_t GmshScanner::integer() {
  const std::string_view text = token();
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    fail("\"" + std::string(text.substr(0, 40)) + "\" is not an integer");
  }
  return value;
}

double GmshScanner::real() {
  const std::string_view text = token();
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    // from_chars refuses "nan"/"inf" spellings it does not know; report the text as written.
    fail("\"" + std::string(text.substr(0, 40)) + "\" is not a number");
  }
  return value;
}

void GmshScanner::fail(const std::string& reason) const {
  std::string where = reason;
  if (!section_.empty()) where += " in " + section_;
  if (!item_.empty()) where += " (" + item_ + ")";
  throw core::InputError(where, {file_, "", ""});
}

}  // namespace viscera::importers
