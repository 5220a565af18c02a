#pragma once
/// Whole numbers read from JSON a user hands the tools. nlohmann::json converts a floating
/// point member to an integer by a cast, which is undefined behaviour when the value is outside
/// the integer's range (the scenario_json fuzz target's finding: a seed of 1.1e67). Every reader
/// that takes an integer out of a user's JSON goes through these checks first, so such a value
/// is a ValidationError naming the member, never undefined behaviour.

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/error.h"

namespace viscera::core {

/// True when `n` is a JSON integer (not a float, however whole) that T can hold.
template <typename T>
bool whole_number_fits(const nlohmann::json& n) {
  static_assert(std::is_integral_v<T> && !std::is_same_v<T, bool>);
  if (n.is_number_unsigned())
    return n.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<T>::max());
  if (!n.is_number_integer()) return false;
  const std::int64_t v = n.get<std::int64_t>();
  if constexpr (std::is_signed_v<T>)
    return v >= std::numeric_limits<T>::min() && v <= std::numeric_limits<T>::max();
  else
    return v >= 0 && static_cast<std::uint64_t>(v) <= std::numeric_limits<T>::max();
}

namespace json_numbers_detail {
template <typename T>
struct element_of {
  using type = void;
};
template <typename U, typename A>
struct element_of<std::vector<U, A>> {
  using type = U;
};
template <typename U, std::size_t N>
struct element_of<std::array<U, N>> {
  using type = U;
};
}  // namespace json_numbers_detail

/// Checks every integer a conversion of `n` to T would take: T itself when it is an integer
/// type, else the elements of vectors and arrays, recursively. Other
/// types are left to nlohmann (its type errors are typed by the readers). Throws
/// ValidationError at `pointer`, extended by the element's index, naming `file`.
template <typename T>
void check_whole_numbers(const nlohmann::json& n, const std::string& file,
                         const std::string& pointer) {
  using Element = typename json_numbers_detail::element_of<T>::type;
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    if (!whole_number_fits<T>(n))
      throw ValidationError("must be a whole number from " +
                                std::to_string(std::numeric_limits<T>::min()) + " to " +
                                std::to_string(std::numeric_limits<T>::max()),
                            {file, pointer, ""});
  } else if constexpr (!std::is_void_v<Element>) {
    if (!n.is_array()) return;
    for (std::size_t i = 0; i < n.size(); ++i)
      check_whole_numbers<Element>(n[i], file, pointer + "/" + std::to_string(i));
  }
}

/// `n` as the integer type T, after whole_number_fits; throws ValidationError at `pointer`.
template <typename T>
T whole_number(const nlohmann::json& n, const std::string& file, const std::string& pointer) {
  check_whole_numbers<T>(n, file, pointer);
  return n.get<T>();
}

/// Converts `n` into `value` with every integer inside checked first. Vectors are converted
/// element by element, so a ValidationError thrown inside an element's own from_json (whose
/// pointer is relative to that element) leaves here with `pointer`, the index and its own
/// pointer joined: the full RFC 6901 pointer into the file.
template <typename T>
void convert_checked(const nlohmann::json& n, T& value, const std::string& file,
                     const std::string& pointer) {
  using Element = typename json_numbers_detail::element_of<T>::type;
  if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
    value = whole_number<T>(n, file, pointer);
  } else if constexpr (std::is_same_v<T, std::vector<Element>>) {
    if (!n.is_array()) {
      n.get_to(value);  // nlohmann's type_error, typed by the reader
      return;
    }
    T converted;
    converted.reserve(n.size());
    for (std::size_t i = 0; i < n.size(); ++i)
      convert_checked(n[i], converted.emplace_back(), file, pointer + "/" + std::to_string(i));
    value = std::move(converted);
  } else {
    check_whole_numbers<T>(n, file, pointer);
    try {
      n.get_to(value);
    } catch (const ValidationError& e) {
      throw ValidationError(e.reason(), {file, pointer + e.location().json_pointer, ""});
    }
  }
}

/// `j[key]` converted into `value` when the member is present (else `value` keeps its
/// default), by convert_checked.
template <typename T>
void read_optional_member(const nlohmann::json& j, const char* key, T& value,
                          const std::string& file = {}, const std::string& pointer = {}) {
  const auto it = j.find(key);
  if (it != j.end()) convert_checked(*it, value, file, pointer + "/" + key);
}

/// `j[key]` converted into `value` by convert_checked; a missing member is nlohmann's
/// out_of_range, typed by the reader as for any other missing member.
template <typename T>
void read_member(const nlohmann::json& j, const char* key, T& value, const std::string& file = {},
                 const std::string& pointer = {}) {
  convert_checked(j.at(key), value, file, pointer + "/" + key);
}

}  // namespace viscera::core
