#include "templates/vessels/vessel_tree_json.h"

#include "core/error.h"
#include "core/json_numbers.h"
#include "templates/vessels/vessel_tree_analysis.h"

namespace viscera::templates {
namespace {

nlohmann::json vec(const core::Vec3& v) {
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

}  // namespace

nlohmann::json vessel_tree_to_json(const core::VesselTree& tree) {
  const auto children = segment_children(tree);
  nlohmann::json segments = nlohmann::json::array();
  for (std::size_t i = 0; i < tree.segments.size(); ++i) {
    const auto& s = tree.segments[i];
    segments.push_back({{"id", s.id},
                        {"parent", s.parent},
                        {"children", children[i]},
                        {"proximal", vec(s.proximal)},
                        {"distal", vec(s.distal)},
                        {"radius", s.radius},
                        {"length", segment_length(s)},
                        {"flow", s.flow}});
  }
  return {{"format", "viscera-vessel-tree"},
          {"version", 1},
          {"units", {{"length", "m"}, {"radius", "m"}, {"flow", "m^3/s"}, {"volume", "m^3"}}},
          {"tree",
           {{"id", tree.id},
            {"host_object", tree.host_object},
            {"kind", tree.kind},
            {"segments", segments}}},
          {"summary",
           {{"segments", tree.segments.size()},
            {"terminals", terminal_count(tree)},
            {"volume", tree_volume(tree)},
            {"murray_max_deviation", murray_deviation(tree)},
            {"intersections", find_intersections(tree).size()}}}};
}

core::VesselTree vessel_tree_from_json(const nlohmann::json& json, const std::string& file) {
  const auto fail = [&](const std::string& pointer, const std::string& message) {
    throw core::ValidationError(message, {file, pointer, ""});
  };
  if (!json.is_object() || json.value("format", std::string()) != "viscera-vessel-tree") {
    fail("/format", "not a viscera vessel tree (format \"viscera-vessel-tree\")");
  }
  if (!json.contains("tree") || !json["tree"].is_object()) fail("/tree", "missing tree");
  const auto& t = json["tree"];
  core::VesselTree tree;
  tree.id = t.value("id", std::string());
  tree.host_object = t.value("host_object", std::string());
  tree.kind = t.value("kind", std::string("arterial"));
  if (!t.contains("segments") || !t["segments"].is_array())
    fail("/tree/segments", "missing segments");
  for (std::size_t i = 0; i < t["segments"].size(); ++i) {
    const auto& j = t["segments"][i];
    const std::string pointer = "/tree/segments/" + std::to_string(i);
    core::VesselSegment s;
    try {
      s.id = core::whole_number<int>(j.at("id"), file, pointer + "/id");
      if (j.contains("parent"))
        s.parent = core::whole_number<int>(j["parent"], file, pointer + "/parent");
      for (int a = 0; a < 3; ++a) {
        s.proximal[a] = j.at("proximal").at(a).get<double>();
        s.distal[a] = j.at("distal").at(a).get<double>();
      }
      s.radius = j.at("radius").get<double>();
      s.flow = j.value("flow", 0.0);
    } catch (const nlohmann::json::exception& e) {
      fail(pointer, std::string("bad segment: ") + e.what());
    }
    tree.segments.push_back(s);
  }
  // Structure only: a hand-made tree may break Murray's law; validate_vessel_tree says so.
  for (const auto& issue : validate_vessel_tree(tree, 1e9)) {
    const bool structural = issue.message.find("intersects") == std::string::npos &&
                            issue.message.find("flow") == std::string::npos;
    if (structural) fail("/tree" + issue.json_pointer, issue.message);
  }
  return tree;
}

}  // namespace viscera::templates
