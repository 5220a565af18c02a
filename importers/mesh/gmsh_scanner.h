#pragma once
/// Reading the tokens and binary fields of a .msh file held in memory, with errors that name
/// the file, the section and what was being read. Internal to the gmsh reader.

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "core/error.h"

namespace viscera::importers {

class GmshScanner {
 public:
  GmshScanner(std::string bytes, std::string file)
      : bytes_(std::move(bytes)), file_(std::move(file)) {}

  /// Names the section being read ("$Nodes") for error messages.
  void enter(std::string section) { section_ = std::move(section); }
  /// Describes the item being read ("node 12 of 40") for error messages; empty for none.
  void at(std::string item) { item_ = std::move(item); }
  /// Binary fields are byte-swapped when the file was written on a machine of the other order.
  void set_swap(bool swap) { swap_ = swap; }

  bool at_end() const { return position_ >= bytes_.size(); }
  /// Bytes not read yet: a bound on how many items a header may claim before anything is
  /// allocated for them.
  std::size_t remaining() const { return at_end() ? 0 : bytes_.size() - position_; }
  /// Throws unless `count` items of at least `bytes_each` bytes fit in the rest of the file.
  void check_claim(std::uint64_t count, std::size_t bytes_each, const std::string& what) const {
    if (count > remaining() / bytes_each) {
      fail("the header claims " + std::to_string(count) + " " + what +
           " but the file ends before them");
    }
  }

  /// The next line without its end-of-line characters.
  std::string_view line();
  /// The next non-empty line, trimmed; throws at the end of the file.
  std::string_view next_line();
  /// Throws unless the next non-empty line is `expected` (e.g. "$EndNodes").
  void expect_line(std::string_view expected);
  /// Skips lines up to and including `end` (an unknown section's "$End…").
  void skip_past(std::string_view end);

  /// The next whitespace-separated ASCII token.
  std::string_view token();
  std::int64_t integer();
  double real();

  /// The next binary field of type T in the file's byte order.
  template <typename T>
  T binary() {
    if (bytes_.size() - position_ < sizeof(T) || position_ > bytes_.size()) truncated();
    T value;
    std::memcpy(&value, bytes_.data() + position_, sizeof(T));
    position_ += sizeof(T);
    if (swap_) value = byteswapped(value);
    return value;
  }

  /// Throws core::InputError: "<file>: <reason> in <section> (<item>)".
  [[noreturn]] void fail(const std::string& reason) const;
  [[noreturn]] void truncated() const { fail("the file ends early"); }

 private:
  template <typename T>
  static T byteswapped(T value) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
      std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  std::string bytes_;
  std::string file_;
  std::string section_;
  std::string item_;
  std::size_t position_ = 0;
  bool swap_ = false;
};

}  // namespace viscera::importers
