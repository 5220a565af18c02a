#include "templates/vessels/spline_vessel_tree.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "templates/vessels/vessel_tree_analysis.h"

namespace viscera::templates {
namespace {

using core::Vec3;

/// Arc-length position `fraction` ∈ [0, 1] along a polyline; inserts a vertex there unless one
/// is already within `tolerance`, and returns that vertex's index.
std::size_t insert_at_fraction(std::vector<Vec3>& line, double fraction, double tolerance) {
  double total = 0.0;
  for (std::size_t i = 1; i < line.size(); ++i)
    total += (line[i] - line[i - 1]).norm();
  const double target = fraction * total;
  double walked = 0.0;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const double piece = (line[i] - line[i - 1]).norm();
    if (walked + piece >= target || i + 1 == line.size()) {
      const double t = piece > 0.0 ? std::clamp((target - walked) / piece, 0.0, 1.0) : 0.0;
      const Vec3 p = line[i - 1] + t * (line[i] - line[i - 1]);
      if ((p - line[i - 1]).norm() <= tolerance) return i - 1;
      if ((p - line[i]).norm() <= tolerance) return i;
      line.insert(line.begin() + static_cast<std::ptrdiff_t>(i), p);
      return i;
    }
    walked += piece;
  }
  return line.size() - 1;
}

}  // namespace

std::vector<Vec3> sample_catmull_rom(const std::vector<Vec3>& points, double spacing,
                                     core::KnotSpacing knots) {
  const core::CatmullRomSpline spline(points, knots, false);
  std::vector<Vec3> line = {points.front()};
  for (int s = 0; s < spline.segments(); ++s) {
    const double chord = (points[s + 1] - points[s]).norm();
    const int pieces =
        spacing > 0.0 ? std::max(1, static_cast<int>(std::ceil(chord / spacing))) : 1;
    for (int k = 1; k < pieces; ++k)
      line.push_back(spline.evaluate(s, static_cast<double>(k) / pieces));
    line.push_back(points[s + 1]);  // exactly through the control point
  }
  return line;
}

core::VesselTree spline_vessel_tree(const std::vector<SplineVesselBranch>& branches,
                                    const SplineVesselOptions& options) {
  if (branches.empty()) throw core::UsageError("a spline vessel tree needs at least one branch");
  std::vector<std::vector<Vec3>> lines(branches.size());
  std::vector<Vec3> attach_point(branches.size());
  for (std::size_t b = 0; b < branches.size(); ++b) {
    const auto& branch = branches[b];
    const std::string name = "branch " + std::to_string(b);
    if (branch.control_points.size() < 2)
      throw core::UsageError(name + " needs at least two points");
    if (branch.parent_branch < -1 || branch.parent_branch >= static_cast<int>(b)) {
      throw core::UsageError(name + ": parent must be -1 or an earlier branch");
    }
    if (!(branch.attach >= 0.0 && branch.attach <= 1.0))
      throw core::UsageError(name + ": attach must lie in [0, 1]");
    if (!(branch.flow_weight > 0.0))
      throw core::UsageError(name + ": flow_weight must be positive");
    std::vector<Vec3> points = branch.control_points;
    if (branch.parent_branch >= 0) {
      auto& parent = lines[branch.parent_branch];
      const std::size_t node =
          insert_at_fraction(parent, branch.attach, 1e-9 * options.sample_spacing);
      attach_point[b] = parent[node];
      points[0] = parent[node];
    }
    lines[b] = sample_catmull_rom(points, options.sample_spacing, options.knots);
  }

  core::VesselTree tree;
  tree.id = options.tree_id;
  tree.host_object = options.host_object;
  std::vector<std::vector<int>> ending_at(branches.size());  // segment ending at each vertex
  std::vector<std::size_t> last_segment(branches.size());
  for (std::size_t b = 0; b < branches.size(); ++b) {
    const auto& line = lines[b];
    ending_at[b].assign(line.size(), -1);
    int parent = -1;
    if (branches[b].parent_branch >= 0) {
      const auto& parent_line = lines[branches[b].parent_branch];
      const auto it = std::find(parent_line.begin(), parent_line.end(), attach_point[b]);
      parent =
          ending_at[branches[b].parent_branch][static_cast<std::size_t>(it - parent_line.begin())];
    }
    ending_at[b][0] = parent;  // a child attached at 0 continues what feeds this branch
    for (std::size_t k = 1; k < line.size(); ++k) {
      if (!((line[k] - line[k - 1]).norm() > 0.0)) {
        ending_at[b][k] = parent;
        continue;
      }
      core::VesselSegment s;
      s.id = static_cast<int>(tree.segments.size());
      s.parent = parent;
      s.proximal = line[k - 1];
      s.distal = line[k];
      tree.segments.push_back(s);
      parent = s.id;
      ending_at[b][k] = s.id;
    }
    last_segment[b] = static_cast<std::size_t>(parent);
  }
  const auto children = segment_children(tree);
  std::vector<double> weights;
  for (std::size_t i = 0; i < children.size(); ++i) {
    if (!children[i].empty()) continue;
    double weight = 1.0;
    for (std::size_t b = 0; b < branches.size(); ++b) {
      if (last_segment[b] == i) weight = branches[b].flow_weight;
    }
    weights.push_back(weight);
  }
  assign_murray_flows_and_radii(tree, options.root_radius, options.total_flow, weights);
  return tree;
}

std::vector<SplineVesselBranch> spline_branches_from_json(const nlohmann::json& json) {
  const auto fail = [](const std::string& pointer, const std::string& message) {
    throw core::ValidationError(message, {"", pointer, ""});
  };
  if (!json.is_object() || !json.contains("branches") || !json["branches"].is_array()) {
    fail("/branches", "expected an array of branches");
  }
  std::vector<SplineVesselBranch> branches;
  for (std::size_t b = 0; b < json["branches"].size(); ++b) {
    const auto& j = json["branches"][b];
    const std::string pointer = "/branches/" + std::to_string(b);
    SplineVesselBranch branch;
    if (!j.contains("points") || !j["points"].is_array())
      fail(pointer + "/points", "expected [[x, y, z], …]");
    for (std::size_t k = 0; k < j["points"].size(); ++k) {
      const auto& p = j["points"][k];
      if (!p.is_array() || p.size() != 3 || !p[0].is_number() || !p[1].is_number() ||
          !p[2].is_number()) {
        fail(pointer + "/points/" + std::to_string(k), "expected [x, y, z] in m");
      }
      branch.control_points.emplace_back(p[0].get<double>(), p[1].get<double>(),
                                         p[2].get<double>());
    }
    if (j.contains("parent") && !j["parent"].is_number_integer())
      fail(pointer + "/parent", "expected an integer");
    if (j.contains("attach") && !j["attach"].is_number())
      fail(pointer + "/attach", "expected a number");
    if (j.contains("flow_weight") && !j["flow_weight"].is_number())
      fail(pointer + "/flow_weight", "expected a number");
    branch.parent_branch = j.value("parent", -1);
    branch.attach = j.value("attach", 1.0);
    branch.flow_weight = j.value("flow_weight", 1.0);
    branches.push_back(std::move(branch));
  }
  return branches;
}

}  // namespace viscera::templates
