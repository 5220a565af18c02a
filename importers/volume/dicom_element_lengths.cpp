#include "importers/volume/dicom_element_lengths.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <set>

#include "importers/volume/format_readers.h"

namespace viscera::importers::detail {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kUndefinedLength = 0xffffffffu;
/// Nesting the walk follows before it leaves the file to GDCM.
constexpr int kDepthLimit = 32;

struct Syntax {
  bool explicit_vr = true;
  bool big_endian = false;
  /// A compressed transfer syntax: pixel data is encapsulated in fragments (PS3.5 §A.4).
  bool encapsulated = false;
};

struct Tag {
  std::uint16_t group = 0, element = 0;
  bool operator==(const Tag&) const = default;
};

constexpr Tag kItem{0xfffe, 0xe000}, kItemEnd{0xfffe, 0xe00d}, kSequenceEnd{0xfffe, 0xe0dd};
constexpr Tag kPixelData{0x7fe0, 0x0010};

/// The walk met a structure it does not follow: GDCM decides about the file.
struct NotFollowed {};
/// A declared length the file cannot hold, and the sentence saying so.
struct Refusal {
  std::string reason;
};

bool is_vr(const std::string& vr) {
  static const std::set<std::string> known = {"AE", "AS", "AT", "CS", "DA", "DS", "DT", "FD", "FL",
                                              "IS", "LO", "LT", "OB", "OD", "OF", "OL", "OV", "OW",
                                              "PN", "SH", "SL", "SQ", "SS", "ST", "SV", "TM", "UC",
                                              "UI", "UL", "UN", "UR", "US", "UT", "UV"};
  return known.count(vr) > 0;
}

/// VRs whose explicit length is 4 bytes after 2 reserved ones (PS3.5 Table 7.1-1).
bool has_long_length(const std::string& vr) {
  static const std::set<std::string> long_form = {"OB", "OD", "OF", "OL", "OV", "OW", "SQ",
                                                  "SV", "UC", "UN", "UR", "UT", "UV"};
  return long_form.count(vr) > 0;
}

std::string tag_text(Tag tag) {
  char text[16];
  std::snprintf(text, sizeof text, "(%04X,%04X)", tag.group, tag.element);
  return text;
}

/// One element's (or item's) header: where its value starts and how long it says it is.
struct Header {
  Tag tag;
  std::string vr;  ///< empty for items, delimiters and implicit VR
  std::uint64_t value = 0;
  std::uint32_t length = 0;
};

class ElementWalk {
 public:
  ElementWalk(const fs::path& path, std::uint64_t size)
      : in_(path, std::ios::binary), size_(size) {}

  /// The group number at `at` (file meta elements are little endian).
  std::uint16_t group_at(std::uint64_t at) { return number16(&bytes(at, 2)[0], false); }

  /// The header at `at`. An element whose VR is not a VR is read as implicit VR (a 4-byte
  /// length after the tag), as GDCM reads it, in the file meta group too.
  Header header(std::uint64_t at, Syntax syntax) {
    const auto head = bytes(at, 8);
    Header h;
    h.tag = {number16(&head[0], syntax.big_endian), number16(&head[2], syntax.big_endian)};
    const bool item_or_delimiter = h.tag.group == 0xfffe;  // no VR in any syntax
    if (syntax.explicit_vr && !item_or_delimiter) {
      const std::string vr{static_cast<char>(head[4]), static_cast<char>(head[5])};
      if (is_vr(vr)) {
        h.vr = vr;
        if (has_long_length(vr)) {
          const auto longer = bytes(at, 12);
          h.length = number32(&longer[8], syntax.big_endian);
          h.value = at + 12;
        } else {
          h.length = number16(&head[6], syntax.big_endian);
          h.value = at + 8;
        }
        return h;
      }
    }
    h.length = number32(&head[4], syntax.big_endian);
    h.value = at + 8;
    return h;
  }

  /// Elements from `at` to `end`, or to the delimiter of an item of undefined length; returns
  /// the offset after them.
  std::uint64_t elements(std::uint64_t at, std::uint64_t end, Syntax syntax, int depth,
                         bool until_item_end) {
    if (depth > kDepthLimit) throw NotFollowed{};
    while (at < end) {
      const Header h = header(at, syntax);
      if (until_item_end && h.tag == kItemEnd) return h.value;
      if (h.tag.group == 0xfffe) throw NotFollowed{};
      at = value_end(h, at, end, syntax, depth);
    }
    if (until_item_end) throw NotFollowed{};
    return at;
  }

  std::string text(std::uint64_t at, std::uint32_t length) {
    std::string value(length, '\0');
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(value.data(), static_cast<std::streamsize>(length));
    return value;
  }

  std::uint64_t size() const { return size_; }

 private:
  std::array<unsigned char, 12> bytes(std::uint64_t at, int count) {
    std::array<unsigned char, 12> out{};
    if (at > size_ || size_ - at < static_cast<std::uint64_t>(count)) throw NotFollowed{};
    in_.seekg(static_cast<std::streamoff>(at));
    if (!in_.read(reinterpret_cast<char*>(out.data()), count)) throw NotFollowed{};
    return out;
  }

  static std::uint16_t number16(const unsigned char* b, bool big) {
    return static_cast<std::uint16_t>(big ? b[0] << 8 | b[1] : b[1] << 8 | b[0]);
  }
  static std::uint32_t number32(const unsigned char* b, bool big) {
    std::uint32_t value = 0;
    for (int i = 0; i < 4; ++i)
      value = value << 8 | b[big ? i : 3 - i];
    return value;
  }

  /// Refuses a value of `length` bytes from `value` on that runs past the end of the file.
  void check_fits(const Header& h, std::uint64_t at, bool fragment) const {
    if (h.length <= size_ - h.value) return;
    const std::string declares = " at byte " + std::to_string(at) + " declares " +
                                 std::to_string(h.length) + " bytes, the file holds " +
                                 std::to_string(size_ - h.value) + " after it";
    if (fragment) throw Refusal{"pixel data is truncated: the fragment" + declares};
    if (h.tag == kPixelData)
      throw Refusal{"pixel data is truncated: " + tag_text(h.tag) + declares};
    if (h.tag == kItem) throw Refusal{"damaged DICOM data element: the sequence item" + declares};
    throw Refusal{"damaged DICOM data element " + tag_text(h.tag) + declares};
  }

  /// The offset after the value of element `h` (at `at`), walking into its items.
  std::uint64_t value_end(const Header& h, std::uint64_t at, std::uint64_t end, Syntax syntax,
                          int depth) {
    if (h.length == kUndefinedLength) {
      // A sequence, an explicit UN holding one in implicit VR (CP-246), or encapsulated pixels.
      const bool pixels = h.tag == kPixelData && (h.vr == "OB" || h.vr == "OW" || h.vr.empty());
      // Only a compressed transfer syntax encapsulates pixel data (undefined length, then
      // fragments); in a native one the length is the image's (PS3.5 §A.4). GDCM reads such a
      // file on as elements out of the pixels and allocates what their bytes declare.
      if (pixels && depth == 0 && !syntax.encapsulated) {
        throw Refusal{"pixel data is damaged: " + tag_text(h.tag) + " at byte " +
                      std::to_string(at) +
                      " has an undefined length, which only a compressed transfer syntax allows"};
      }
      if (syntax.explicit_vr && h.vr != "SQ" && h.vr != "UN" && !pixels) throw NotFollowed{};
      Syntax nested = syntax;
      if (h.vr == "UN") nested.explicit_vr = false;
      return items(h.value, end, nested, depth + 1, pixels);
    }
    check_fits(h, at, false);
    const std::uint64_t after = h.value + h.length;
    if (after > end) throw NotFollowed{};  // runs past its item
    if (h.vr == "SQ") {
      for (std::uint64_t item = h.value; item < after;)
        item = item_end(header(item, syntax), item, after, syntax, depth + 1, false);
    }
    return after;
  }

  /// Items (or fragments) of undefined-length `h` up to the sequence delimiter; returns the
  /// offset after it.
  std::uint64_t items(std::uint64_t at, std::uint64_t end, Syntax syntax, int depth,
                      bool fragments) {
    if (depth > kDepthLimit) throw NotFollowed{};
    for (;;) {
      const Header h = header(at, syntax);
      if (h.tag == kSequenceEnd) return h.value;
      if (fragments && !(h.tag == kItem)) {
        throw Refusal{"pixel data is damaged: encapsulated pixel data holds " + tag_text(h.tag) +
                      " at byte " + std::to_string(at) + " where a fragment item must be"};
      }
      at = item_end(h, at, end, syntax, depth, fragments);
    }
  }

  std::uint64_t item_end(const Header& h, std::uint64_t at, std::uint64_t end, Syntax syntax,
                         int depth, bool fragment) {
    if (!(h.tag == kItem)) throw NotFollowed{};
    if (h.length == kUndefinedLength) {
      if (fragment) throw NotFollowed{};
      return elements(h.value, end, syntax, depth + 1, true);
    }
    check_fits(h, at, fragment);
    const std::uint64_t after = h.value + h.length;
    if (after > end) throw NotFollowed{};
    if (!fragment) elements(h.value, after, syntax, depth + 1, false);
    return after;
  }

  std::ifstream in_;
  std::uint64_t size_;
};

/// The transfer syntax UID without its padding.
std::string trimmed(std::string uid) {
  while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' '))
    uid.pop_back();
  return uid;
}

}  // namespace

std::optional<std::string> dicom_length_problem(const fs::path& path) {
  std::error_code error;
  const std::uint64_t size = fs::file_size(path, error);
  if (error || !has_dicom_magic(path)) return std::nullopt;
  ElementWalk walk(path, size);
  try {
    // The file meta group, always explicit VR little endian.
    const Syntax meta{true, false};
    std::uint64_t at = 132;
    std::string uid;
    while (walk.group_at(at) == 0x0002) {
      const Header h = walk.header(at, meta);
      if (h.length == kUndefinedLength) throw NotFollowed{};
      if (h.length > size - h.value) {
        return "damaged DICOM data element " + tag_text(h.tag) + " at byte " + std::to_string(at) +
               " declares " + std::to_string(h.length) + " bytes, the file holds " +
               std::to_string(size - h.value) + " after it";
      }
      if (h.tag.element == 0x0010) uid = trimmed(walk.text(h.value, std::min(h.length, 64u)));
      at = h.value + h.length;
    }
    // No transfer syntax (GDCM guesses one) or a deflated data set: not walked.
    if (uid.empty() || uid == "1.2.840.10008.1.2.1.99") return std::nullopt;
    const bool native =
        uid == "1.2.840.10008.1.2" || uid == "1.2.840.10008.1.2.1" || uid == "1.2.840.10008.1.2.2";
    const Syntax syntax{uid != "1.2.840.10008.1.2", uid == "1.2.840.10008.1.2.2", !native};
    walk.elements(at, size, syntax, 0, false);
  } catch (const NotFollowed&) {
    return std::nullopt;
  } catch (const Refusal& refusal) {
    return refusal.reason;
  }
  return std::nullopt;
}

}  // namespace viscera::importers::detail
