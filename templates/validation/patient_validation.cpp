#include "templates/validation/patient_validation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "core/error.h"
#include "core/mesh/tet_quality.h"
#include "templates/geometry/surface_queries.h"
#include "textures/scenario_baking.h"

namespace viscera::templates {
namespace {

/// Objects whose surface bounds a solid: tet and mass-spring bodies (cell sheets and the
/// urethra lattice are open).
bool bounds_solid(const core::SceneObject& object) {
  return object.body_kind == core::BodyKind::TetMesh ||
         object.body_kind == core::BodyKind::MassSpring;
}

bool all_finite(const std::vector<core::Vec3>& points) {
  for (const auto& p : points) {
    if (!p.allFinite()) return false;
  }
  return true;
}

core::SceneObject const* find(const core::Scenario& s, const std::string& id) {
  return id.empty() ? nullptr : s.find_object(id);
}

ValidationCheck check_surfaces(const core::Scenario& scenario) {
  ValidationCheck check{"surfaces", true, "", {}};
  int checked = 0;
  for (const auto& object : scenario.objects) {
    if (!all_finite(object.surface.vertices)) {
      check = {"surfaces", false, "object " + object.id + ": surface has a non-finite vertex", {}};
      return check;
    }
    if (!bounds_solid(object)) continue;
    ++checked;
    if (!core::is_closed_and_consistently_oriented(object.surface)) {
      check.passed = false;
      check.detail = "object " + object.id + ": surface is not closed and consistently oriented";
    } else if (core::enclosed_volume(object.surface) <= 0.0) {
      check.passed = false;
      check.detail = "object " + object.id + ": surface is oriented inward";
    } else if (self_intersects(object.surface)) {
      check.passed = false;
      check.detail = "object " + object.id + ": surface intersects itself";
    }
    if (!check.passed) return check;
  }
  check.measures["watertight_surfaces"] = checked;
  return check;
}

ValidationCheck check_overlap(const core::Scenario& scenario) {
  ValidationCheck check{"overlap", true, "", {}};
  std::map<std::string, std::string> host_of;
  for (const auto& p : scenario.pathologies)
    host_of[p.object] = p.host_object;
  int pairs = 0;
  const auto& objects = scenario.objects;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (!bounds_solid(objects[i])) continue;
    const core::BoundingBox box_i = core::bounds(objects[i].surface);
    for (std::size_t j = i + 1; j < objects.size(); ++j) {
      if (!bounds_solid(objects[j])) continue;
      const core::BoundingBox box_j = core::bounds(objects[j].surface);
      if ((box_i.min.array() > box_j.max.array()).any() ||
          (box_j.min.array() > box_i.max.array()).any())
        continue;
      ++pairs;
      // A host holds its intramural pathologies (holes in its body): only crossing surfaces
      // count between a host and its own pathology; any overlap counts between others.
      const bool host_pair =
          host_of[objects[i].id] == objects[j].id || host_of[objects[j].id] == objects[i].id;
      const bool bad = host_pair ? surfaces_cross(objects[i].surface, objects[j].surface)
                                 : surfaces_intersect(objects[i].surface, objects[j].surface);
      if (bad) {
        check.passed = false;
        check.detail = "objects " + objects[i].id + " and " + objects[j].id + " overlap";
        return check;
      }
    }
  }
  check.measures["pairs_tested"] = pairs;
  return check;
}

ValidationCheck check_tets(const core::Scenario& scenario, const ValidationBounds& bounds) {
  ValidationCheck check{"tets", true, "", {}};
  double worst = std::numeric_limits<double>::infinity();
  std::size_t tets = 0, inverted = 0;
  for (const auto& object : scenario.objects) {
    if (object.body_kind != core::BodyKind::TetMesh) continue;
    try {
      core::check_tet_mesh(object.body, "object " + object.id + " body");
    } catch (const core::Error& e) {
      check = {"tets", false, e.what(), {}};
      return check;
    }
    const core::TetQualityReport report = core::tet_quality(object.body);
    tets += report.tets;
    inverted += report.inverted;
    if (report.inverted > 0 && check.passed) {
      check.passed = false;
      check.detail =
          "object " + object.id + ": " + std::to_string(report.inverted) + " inverted tets";
    }
    if (report.tets > 0 && !std::isnan(report.min_dihedral_degrees)) {
      worst = std::min(worst, report.min_dihedral_degrees);
      if (report.min_dihedral_degrees < bounds.min_dihedral_degrees && check.passed) {
        std::ostringstream out;
        out << "object " << object.id << ": smallest dihedral angle " << report.min_dihedral_degrees
            << "° is below " << bounds.min_dihedral_degrees << "°";
        check.passed = false;
        check.detail = out.str();
      }
    }
  }
  check.measures["tets"] = tets;
  check.measures["inverted"] = inverted;
  check.measures["min_dihedral_degrees"] = std::isfinite(worst) ? nlohmann::json(worst) : nullptr;
  check.measures["min_dihedral_bound_degrees"] = bounds.min_dihedral_degrees;
  return check;
}

/// True when the host triangle nearest to `p` has every vertex on the cavity wall.
bool nearest_wall_is_cavity(const core::SceneObject& host, const SurfaceQueries& tissue,
                            const core::Vec3& p) {
  const auto it = host.surface.vertex_attributes.find("cavity");
  if (it == host.surface.vertex_attributes.end()) return true;
  const auto& tri = host.surface.triangles[static_cast<std::size_t>(tissue.closest(p).triangle)];
  for (const int v : tri) {
    if (it->second[static_cast<std::size_t>(v)] != 1.0) return false;
  }
  return true;
}

ValidationCheck check_pathologies(const core::Scenario& scenario, const ValidationBounds& bounds) {
  ValidationCheck check{"pathologies", true, "", {}};
  std::map<std::string, std::unique_ptr<SurfaceQueries>> hosts;
  const auto fail = [&](const std::string& why) {
    check.passed = false;
    check.detail = why;
    return check;
  };
  for (const auto& pathology : scenario.pathologies) {
    const core::SceneObject* host = find(scenario, pathology.host_object);
    const core::SceneObject* object = find(scenario, pathology.object);
    if (host == nullptr) return fail(pathology.id + ": host " + pathology.host_object + " missing");
    if (object == nullptr) return fail(pathology.id + ": object " + pathology.object + " missing");
    if (!hosts.contains(host->id)) {
      try {
        hosts[host->id] = std::make_unique<SurfaceQueries>(host->surface, "object " + host->id);
      } catch (const core::Error& e) {
        return fail(pathology.id + ": " + e.what());
      }
    }
    const SurfaceQueries& tissue = *hosts[host->id];
    const bool in_wall = pathology.kind == "myoma-intramural";
    core::Vec3 centroid = core::Vec3::Zero();
    for (const auto& v : object->surface.vertices) {
      centroid += v;
      const bool inside = tissue.inside(v);
      if (in_wall && !inside) return fail(pathology.id + " reaches out of the wall of " + host->id);
      if (!in_wall && inside && tissue.closest(v).distance > bounds.wall_tolerance)
        return fail(pathology.id + " enters the wall of " + host->id);
    }
    if (object->surface.vertices.empty()) return fail(pathology.id + " has no surface");
    centroid /= static_cast<double>(object->surface.vertices.size());
    if (!in_wall && !nearest_wall_is_cavity(*host, tissue, centroid))
      return fail(pathology.id + " is not in the cavity of " + host->id);
  }
  check.measures["pathologies"] = scenario.pathologies.size();
  return check;
}

ValidationCheck check_attachments(const core::Scenario& scenario) {
  ValidationCheck check{"attachments", true, "", {}};
  for (const auto& pathology : scenario.pathologies) {
    std::size_t pairs = 0;
    for (const auto& c : scenario.connections) {
      if ((c.object_a == pathology.host_object && c.object_b == pathology.object) ||
          (c.object_b == pathology.host_object && c.object_a == pathology.object))
        pairs += c.node_pairs.size();
    }
    if (pairs < 3) {
      check.passed = false;
      check.detail = pathology.id + " is attached to " + pathology.host_object + " by " +
                     std::to_string(pairs) + " node pairs (at least 3 needed)";
      return check;
    }
  }
  check.measures["attached"] = scenario.pathologies.size();
  return check;
}

/// Per node of `object`'s body, the length in m of the longest tet edge that meets it.
std::vector<double> longest_edge_at_nodes(const core::SceneObject& object) {
  const auto& nodes = object.body.nodes;
  std::vector<double> longest(nodes.size(), 0.0);
  for (const auto& tet : object.body.tets) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) {
        const auto a = static_cast<std::size_t>(tet[i]), b = static_cast<std::size_t>(tet[j]);
        if (a >= nodes.size() || b >= nodes.size()) continue;  // the tets check reports it
        const double length = (nodes[a] - nodes[b]).norm();
        longest[a] = std::max(longest[a], length);
        longest[b] = std::max(longest[b], length);
      }
  }
  return longest;
}

ValidationCheck check_connections(const core::Scenario& scenario, const ValidationBounds& bounds) {
  ValidationCheck check{"connections", true, "", {}};
  double widest = 0.0;
  for (const auto& c : scenario.connections) {
    const core::SceneObject* a = find(scenario, c.object_a);
    const core::SceneObject* b = find(scenario, c.object_b);
    std::string why;
    if (a == nullptr || b == nullptr) {
      why = "names a missing object";
    } else if (c.node_pairs.size() < 3) {
      why = "has " + std::to_string(c.node_pairs.size()) + " node pairs";
    } else if (!(c.stiffness > 0.0) || !std::isfinite(c.stiffness)) {
      why = "has no positive stiffness";
    } else {
      const std::vector<double> edge_a = longest_edge_at_nodes(*a);
      const std::vector<double> edge_b = longest_edge_at_nodes(*b);
      for (const auto& [na, nb] : c.node_pairs) {
        if (na < 0 || nb < 0 || na >= static_cast<int>(a->body.nodes.size()) ||
            nb >= static_cast<int>(b->body.nodes.size())) {
          why = "pairs a node its bodies do not have";
          break;
        }
        const double gap = (a->body.nodes[static_cast<std::size_t>(na)] -
                            b->body.nodes[static_cast<std::size_t>(nb)])
                               .norm();
        widest = std::max(widest, gap);
        const double allowed =
            std::max({bounds.max_connection_gap, edge_a[static_cast<std::size_t>(na)],
                      edge_b[static_cast<std::size_t>(nb)]});
        if (!(gap <= allowed)) {
          std::ostringstream out;
          out << "pairs nodes " << gap * 1000.0 << " mm apart (at most " << allowed * 1000.0
              << " mm)";
          why = out.str();
          break;
        }
      }
    }
    if (!why.empty()) {
      check.passed = false;
      check.detail = "connection " + c.id + " " + why;
      return check;
    }
  }
  check.measures["connections"] = scenario.connections.size();
  check.measures["widest_gap"] = widest;
  return check;
}

ValidationCheck check_references(const core::Scenario& scenario) {
  ValidationCheck check{"references", true, "", {}};
  const auto fail = [&](const std::string& why) {
    check.passed = false;
    check.detail = why;
    return check;
  };
  std::size_t segments = 0;
  for (const auto& tree : scenario.vessel_trees) {
    if (!tree.host_object.empty() && find(scenario, tree.host_object) == nullptr)
      return fail("vessel tree " + tree.id + ": host " + tree.host_object + " missing");
    for (std::size_t s = 0; s < tree.segments.size(); ++s) {
      const auto& seg = tree.segments[s];
      if (seg.parent >= static_cast<int>(s) || seg.parent < -1)
        return fail("vessel tree " + tree.id + ": segment " + std::to_string(s) +
                    " has a parent that does not precede it");
      if (!seg.proximal.allFinite() || !seg.distal.allFinite() || !(seg.radius > 0.0) ||
          !std::isfinite(seg.radius))
        return fail("vessel tree " + tree.id + ": segment " + std::to_string(s) +
                    " has non-finite geometry or no positive radius");
    }
    segments += tree.segments.size();
  }
  for (const auto& mark : scenario.landmarks) {
    if (!mark.object.empty() && find(scenario, mark.object) == nullptr)
      return fail("landmark " + mark.id + ": object " + mark.object + " missing");
  }
  check.measures["vessel_segments"] = segments;
  return check;
}

}  // namespace

bool PatientValidation::valid() const {
  for (const auto& c : checks) {
    if (!c.passed) return false;
  }
  return true;
}

std::string PatientValidation::first_failure() const {
  for (const auto& c : checks) {
    if (!c.passed) return c.name + ": " + c.detail;
  }
  return {};
}

nlohmann::json PatientValidation::to_json() const {
  nlohmann::json list = nlohmann::json::object();
  for (const auto& c : checks) {
    nlohmann::json entry = c.measures;
    entry["passed"] = c.passed;
    if (!c.detail.empty()) entry["detail"] = c.detail;
    list[c.name] = entry;
  }
  return {{"valid", valid()}, {"checks", list}};
}

PatientValidation validate_patient_geometry(const core::Scenario& authored,
                                            const ValidationBounds& bounds) {
  // A baked texture cuts an organ's surface at its UV seams; the checks judge the closed
  // surface the cut came from.
  core::Scenario scenario = authored;
  for (auto& object : scenario.objects)
    object.surface = textures::welded_surface(object.surface);
  PatientValidation result;
  result.checks.push_back(check_surfaces(scenario));
  // Overlap and pathology tests need closed surfaces; a failed surface check would only make
  // them report the same defect again.
  if (result.checks.back().passed) {
    result.checks.push_back(check_overlap(scenario));
    result.checks.push_back(check_pathologies(scenario, bounds));
  }
  result.checks.push_back(check_tets(scenario, bounds));
  result.checks.push_back(check_attachments(scenario));
  result.checks.push_back(check_connections(scenario, bounds));
  result.checks.push_back(check_references(scenario));
  return result;
}

}  // namespace viscera::templates
