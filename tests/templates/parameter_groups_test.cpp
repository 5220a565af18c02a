// The catalogue's parameter groups and descriptions (issue 23 §1): every parameter of every
// template has a one-line description and a group the studio's form can show it under, and the
// hysteroscopy template's parameters fall where a clinician looks for them.

#include <gtest/gtest.h>

#include <map>
#include <string>

#include "templates/template_catalog.h"

namespace viscera::templates {
namespace {

TEST(ParameterGroups, every_parameter_has_a_one_line_description_and_a_group_in_the_json) {
  const nlohmann::json catalog = catalog_to_json();
  ASSERT_FALSE(catalog.empty());
  for (const auto& t : catalog) {
    for (const auto& p : t.at("parameters")) {
      const std::string where =
          t.at("name").get<std::string>() + "/" + p.at("name").get<std::string>();
      const std::string description = p.at("description");
      EXPECT_FALSE(description.empty()) << where;
      EXPECT_EQ(description.find('\n'), std::string::npos) << where;
      const std::string group = p.at("group");
      EXPECT_TRUE(group == "anatomy" || group == "pathologies" || group == "tissue" ||
                  group == "vessels" || group == "texture" || group == "meshing")
          << where << ": " << group;
    }
  }
}

TEST(ParameterGroups, hysteroscopy_parameters_are_grouped_as_a_clinician_expects) {
  std::map<std::string, ParameterGroup> groups;
  for (const auto& p : find_template("hysteroscopy").parameters())
    groups[p.name] = parameter_group(p);
  EXPECT_EQ(groups.at("cervix_length"), ParameterGroup::Anatomy);
  EXPECT_EQ(groups.at("flexion"), ParameterGroup::Anatomy);
  EXPECT_EQ(groups.at("cavity_depth"), ParameterGroup::Anatomy);
  EXPECT_EQ(groups.at("polyps"), ParameterGroup::Pathologies);
  EXPECT_EQ(groups.at("submucosal_myomas"), ParameterGroup::Pathologies);
  EXPECT_EQ(groups.at("myoma_diameter"), ParameterGroup::Pathologies);
  EXPECT_EQ(groups.at("adhesion_radius"), ParameterGroup::Pathologies);
  EXPECT_EQ(groups.at("myometrium_stiffness"), ParameterGroup::Tissue);
  EXPECT_EQ(groups.at("density"), ParameterGroup::Tissue);
  EXPECT_EQ(groups.at("fixed_cervix_fraction"), ParameterGroup::Tissue);
  EXPECT_EQ(groups.at("vessel_terminals"), ParameterGroup::Vessels);
  EXPECT_EQ(groups.at("pathology_artery_radius"), ParameterGroup::Vessels);
  EXPECT_EQ(groups.at("texture_size"), ParameterGroup::Texture);
  EXPECT_EQ(groups.at("edge_length"), ParameterGroup::Meshing);
  EXPECT_EQ(to_string(ParameterGroup::Pathologies), "pathologies");
}

}  // namespace
}  // namespace viscera::templates
