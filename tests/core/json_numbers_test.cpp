#include "core/json_numbers.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/error.h"
#include "core/scenario/scenario_json.h"
#include "tests/core/scenario_fixtures.h"

namespace viscera::core {
namespace {

/// The JSON pointer of the ValidationError `work` throws, or "no error".
template <typename Work>
std::string pointer_of_error(Work&& work) {
  try {
    work();
  } catch (const ValidationError& e) {
    return e.location().json_pointer;
  }
  return "no error";
}

TEST(JsonNumbers, whole_numbers_in_range_are_taken_and_others_refused) {
  EXPECT_TRUE(whole_number_fits<int>(nlohmann::json(-7)));
  EXPECT_TRUE(whole_number_fits<int>(nlohmann::json(2147483647)));
  EXPECT_FALSE(whole_number_fits<int>(nlohmann::json(2147483648LL)));
  EXPECT_FALSE(whole_number_fits<std::uint64_t>(nlohmann::json(-1)));
  EXPECT_TRUE(whole_number_fits<std::uint64_t>(nlohmann::json(18446744073709551615ULL)));
  // Floats are refused however whole: nlohmann would cast them, undefined out of range.
  EXPECT_FALSE(whole_number_fits<int>(nlohmann::json(3.0)));
  EXPECT_FALSE(whole_number_fits<long long>(nlohmann::json(1.1e67)));
  EXPECT_FALSE(whole_number_fits<int>(nlohmann::json("3")));
  EXPECT_EQ(whole_number<int>(nlohmann::json(42), "f.json", "/n"), 42);
}

TEST(JsonNumbers, arrays_are_checked_element_by_element_with_the_element_named) {
  const auto pairs = nlohmann::json::parse("[[1, 2], [3, 1e300]]");
  std::vector<std::array<int, 2>> value;
  EXPECT_EQ(pointer_of_error([&] { convert_checked(pairs, value, "f.json", "/pairs"); }),
            "/pairs/1/1");
  const auto good = nlohmann::json::parse("[[1, 2], [3, 4]]");
  convert_checked(good, value, "f.json", "/pairs");
  ASSERT_EQ(value.size(), 2u);
  EXPECT_EQ(value[1][1], 4);
}

TEST(JsonNumbers, scenario_integers_deep_inside_are_refused_with_their_full_pointer) {
  const nlohmann::json json = scenario_to_json(viscera::testing::full_scenario());
  ASSERT_FALSE(json["connections"][0]["node_pairs"].empty());
  ASSERT_FALSE(json["vessel_trees"][0]["segments"].empty());

  nlohmann::json pairs = json;
  pairs["connections"][0]["node_pairs"][1][0] = 1e300;
  EXPECT_EQ(pointer_of_error([&] { scenario_from_json(pairs, "m.json"); }),
            "/scenario/connections/0/node_pairs/1/0");

  nlohmann::json segment = json;
  const auto last = segment["vessel_trees"][0]["segments"].size() - 1;
  segment["vessel_trees"][0]["segments"][last]["id"] = -1e19;
  EXPECT_EQ(pointer_of_error([&] { scenario_from_json(segment, "m.json"); }),
            "/scenario/vessel_trees/0/segments/" + std::to_string(last) + "/id");

  nlohmann::json seed = json;
  seed["provenance"]["seed"] = 1.1e67;
  EXPECT_EQ(pointer_of_error([&] { scenario_from_json(seed, "m.json"); }),
            "/scenario/provenance/seed");

  // The untouched scenario still reads: the checks refuse nothing a writer produces.
  const Scenario back = scenario_from_json(json, "m.json");
  const Scenario original = viscera::testing::full_scenario();
  EXPECT_EQ(back.connections, original.connections);
  EXPECT_EQ(back.vessel_trees, original.vessel_trees);
  EXPECT_EQ(back.cell_tissues, original.cell_tissues);
  EXPECT_EQ(back.provenance, original.provenance);
}

}  // namespace
}  // namespace viscera::core
