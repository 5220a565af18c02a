// The generator's simulated second on malformed cell tissues (issue 21): a cell type index
// outside the tissue's types is a failed check naming the place, not an escaped
// std::out_of_range.
#include "templates/generator/simulation_check.h"

#include <gtest/gtest.h>

#include "templates/template_catalog.h"

namespace viscera::templates {
namespace {

TEST(SimulationCheck, a_cell_type_index_out_of_range_fails_naming_the_place) {
  core::Scenario lab = build_from_template("agent-tissue", {}, 1);
  ASSERT_FALSE(lab.cell_tissues.empty());
  EXPECT_TRUE(simulate_one_second(lab).passed);  // the same lab, well formed, passes
  auto& types = lab.cell_tissues.front().cell_types;
  ASSERT_GT(types.size(), 3u);
  types[3] = static_cast<int>(lab.cell_tissues.front().types.size());
  const ValidationCheck check = simulate_one_second(lab);
  EXPECT_FALSE(check.passed);
  EXPECT_NE(check.detail.find("cell type index"), std::string::npos) << check.detail;
  EXPECT_NE(check.detail.find("/scenario/cell_tissues/0/cell_types/3"), std::string::npos)
      << check.detail;
}

}  // namespace
}  // namespace viscera::templates
