#include "core/modelling/model_document.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/json_eigen.h"
#include "core/scenario/scenario_json.h"

namespace viscera::core {

void from_json(const nlohmann::json& j, ModelKind& kind);

namespace {

bool is_id_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

void check_id(const std::string& id, const std::string& what) {
  if (id.empty() || !std::all_of(id.begin(), id.end(), is_id_character))
    throw UsageError(what + " \"" + id + "\" must be lower-case letters, digits, '_' or '-'");
}

/// Reads member `key` of `object` at JSON pointer `at`, naming `at/key` when it is missing or
/// has the wrong type.
template <typename T>
T member(const nlohmann::json& object, const char* key, const std::string& at,
         const std::string& file) {
  const std::string pointer = at + "/" + key;
  try {
    return object.at(key).get<T>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("missing or mistyped member: ") + e.what(), {file, pointer, ""});
  } catch (const Error& e) {
    throw InputError(e.reason(), {file, pointer, ""});
  }
}

template <typename T>
T optional_member(const nlohmann::json& object, const char* key, const std::string& at,
                  const std::string& file, T fallback) {
  if (!object.contains(key)) return fallback;
  return member<T>(object, key, at, file);
}

nlohmann::json primitive_to_json(const ModelDocument& m) {
  switch (m.kind) {
    case ModelKind::Ball:
      return {{"type", "ball"},
              {"center", m.ball.center},
              {"radius", m.ball.radius},
              {"control_level", m.ball.control_level},
              {"subdivisions", m.ball.subdivisions},
              {"control_points", m.ball.control_points}};
    case ModelKind::Flat:
      return {{"type", "flat"},
              {"rows", m.flat.rows},
              {"cols", m.flat.cols},
              {"thickness", m.flat.thickness},
              {"open", m.flat.open},
              {"steps_per_patch", m.flat.steps_per_patch},
              {"control_points", m.flat.control_points}};
    case ModelKind::Pipe: {
      nlohmann::json branches = nlohmann::json::array();
      for (const auto& b : m.pipe.branches)
        branches.push_back(
            {{"points", b.points}, {"radii", b.radii}, {"parent", b.parent}, {"attach", b.attach}});
      return {{"type", "pipe"},
              {"branches", branches},
              {"start_cap", to_string(m.pipe.start_cap)},
              {"end_cap", to_string(m.pipe.end_cap)},
              {"ring_segments", m.pipe.ring_segments},
              {"axial_spacing", m.pipe.axial_spacing},
              {"blend", m.pipe.blend}};
    }
  }
  return nullptr;
}

void primitive_from_json(const nlohmann::json& p, const std::string& file, ModelDocument& m) {
  const std::string at = "/primitive";
  m.kind = member<ModelKind>(p, "type", at, file);
  if (m.kind == ModelKind::Ball) {
    m.ball.center = member<Vec3>(p, "center", at, file);
    m.ball.radius = member<double>(p, "radius", at, file);
    m.ball.control_level = member<int>(p, "control_level", at, file);
    m.ball.subdivisions = member<int>(p, "subdivisions", at, file);
    m.ball.control_points = member<std::vector<Vec3>>(p, "control_points", at, file);
  } else if (m.kind == ModelKind::Flat) {
    m.flat.rows = member<int>(p, "rows", at, file);
    m.flat.cols = member<int>(p, "cols", at, file);
    m.flat.thickness = member<double>(p, "thickness", at, file);
    m.flat.open = optional_member<bool>(p, "open", at, file, false);
    m.flat.steps_per_patch = optional_member<int>(p, "steps_per_patch", at, file, 6);
    m.flat.control_points = member<std::vector<Vec3>>(p, "control_points", at, file);
  } else {
    const auto branches = member<nlohmann::json>(p, "branches", at, file);
    if (!branches.is_array())
      throw InputError("branches must be an array", {file, at + "/branches", ""});
    m.pipe.branches.clear();
    for (std::size_t i = 0; i < branches.size(); ++i) {
      const std::string b_at = at + "/branches/" + std::to_string(i);
      PipeBranch b;
      b.points = member<std::vector<Vec3>>(branches[i], "points", b_at, file);
      b.radii = member<std::vector<double>>(branches[i], "radii", b_at, file);
      b.parent = member<int>(branches[i], "parent", b_at, file);
      b.attach = member<double>(branches[i], "attach", b_at, file);
      m.pipe.branches.push_back(std::move(b));
    }
    m.pipe.start_cap = pipe_cap_from_string(member<std::string>(p, "start_cap", at, file));
    m.pipe.end_cap = pipe_cap_from_string(member<std::string>(p, "end_cap", at, file));
    m.pipe.ring_segments = optional_member<int>(p, "ring_segments", at, file, 32);
    m.pipe.axial_spacing = optional_member<double>(p, "axial_spacing", at, file, 0.0);
    m.pipe.blend = optional_member<double>(p, "blend", at, file, 0.6);
  }
}

}  // namespace

std::string to_string(ModelKind kind) {
  switch (kind) {
    case ModelKind::Ball:
      return "ball";
    case ModelKind::Flat:
      return "flat";
    case ModelKind::Pipe:
      return "pipe";
  }
  return "ball";
}

ModelKind model_kind_from_string(const std::string& name) {
  if (name == "ball") return ModelKind::Ball;
  if (name == "flat") return ModelKind::Flat;
  if (name == "pipe") return ModelKind::Pipe;
  throw UsageError("a model is a ball, flat or pipe, not \"" + name + "\"");
}

void from_json(const nlohmann::json& j, ModelKind& kind) {
  kind = model_kind_from_string(j.get<std::string>());
}

void check_model(const ModelDocument& m) {
  check_id(m.id, "the model id");
  const std::string what = "model \"" + m.id + "\"";
  switch (m.kind) {
    case ModelKind::Ball:
      check_ball(m.ball, what);
      break;
    case ModelKind::Flat:
      check_flat(m.flat, what);
      break;
    case ModelKind::Pipe:
      check_pipe_network(m.pipe, what);
      break;
  }
  if (m.layering) {
    const auto& l = m.layering->layers;
    if (l.layers < 1 || !(l.thickness > 0.0) || !std::isfinite(l.thickness))
      throw UsageError(what + ": layering needs at least one layer and a positive thickness");
    if (m.layering->cell_size < 0.0 || !std::isfinite(m.layering->cell_size))
      throw UsageError(what + ": the layer cell size must not be negative");
  }
  for (const auto& f : m.fixed) {
    if (!(f.radius > 0.0) || !f.center.allFinite())
      throw UsageError(what + ": a fixed region needs a finite centre and a positive radius");
  }
  for (const auto& c : m.connections) {
    check_id(c.object, what + ": the connected object");
    if (c.object == m.id) throw UsageError(what + " cannot be connected to itself");
    if (!(c.distance > 0.0) || !(c.stiffness > 0.0))
      throw UsageError(what + ": a connection needs a positive distance and stiffness");
  }
  if (m.material) check_id(m.material->id, what + ": the material id");
}

std::vector<Vec3> model_control_points(const ModelDocument& m) {
  switch (m.kind) {
    case ModelKind::Ball:
      return m.ball.control_points;
    case ModelKind::Flat:
      return m.flat.control_points;
    case ModelKind::Pipe:
      return network_control_points(m.pipe);
  }
  return {};
}

void move_model_control_point(ModelDocument& m, int index, const Vec3& position) {
  if (!position.allFinite()) throw UsageError("a control point must be finite");
  const auto count = static_cast<int>(model_control_points(m).size());
  if (index < 0 || index >= count)
    throw UsageError("model \"" + m.id + "\" has control points 0 to " + std::to_string(count - 1) +
                     ", not " + std::to_string(index));
  const auto i = static_cast<std::size_t>(index);
  switch (m.kind) {
    case ModelKind::Ball:
      m.ball.control_points[i] = position;
      break;
    case ModelKind::Flat:
      m.flat.control_points[i] = position;
      break;
    case ModelKind::Pipe: {
      const auto [branch, point] = locate_control_point(m.pipe, index);
      m.pipe.branches[static_cast<std::size_t>(branch)].points[static_cast<std::size_t>(point)] =
          position;
      break;
    }
  }
}

int add_model_branch(ModelDocument& m, const PipeBranch& branch) {
  if (m.kind != ModelKind::Pipe)
    throw UsageError("model \"" + m.id + "\" is a " + to_string(m.kind) + ", not a pipe");
  PipeNetwork grown = m.pipe;
  grown.branches.push_back(branch);
  check_pipe_network(grown, "model \"" + m.id + "\"");
  m.pipe = std::move(grown);
  return static_cast<int>(m.pipe.branches.size()) - 1;
}

nlohmann::json model_to_json(const ModelDocument& m) {
  nlohmann::json json = {{"format", kModelFormat},
                         {"version", kModelFormatVersion},
                         {"id", m.id},
                         {"name", m.name},
                         {"role", to_string(m.role)},
                         {"group", m.group},
                         {"primitive", primitive_to_json(m)}};
  json["layering"] = nullptr;
  if (m.layering) {
    json["layering"] = {{"layers", m.layering->layers.layers},
                        {"thickness", m.layering->layers.thickness},
                        {"mode", to_string(m.layering->layers.mode)},
                        {"body", m.layering->mass_spring ? "mass-spring" : "tets"},
                        {"cell_size", m.layering->cell_size}};
  }
  json["material"] = m.material ? nlohmann::json(*m.material) : nlohmann::json(nullptr);
  json["fixed"] = nlohmann::json::array();
  for (const auto& f : m.fixed)
    json["fixed"].push_back({{"center", f.center}, {"radius", f.radius}});
  json["connections"] = nlohmann::json::array();
  for (const auto& c : m.connections)
    json["connections"].push_back(
        {{"object", c.object}, {"distance", c.distance}, {"stiffness", c.stiffness}});
  return json;
}

ModelDocument model_from_json(const nlohmann::json& json, const std::string& file) {
  if (!json.is_object()) throw InputError("a model document is a JSON object", {file, "", ""});
  if (member<std::string>(json, "format", "", file) != kModelFormat)
    throw InputError(std::string("not a Viscera model (format is not \"") + kModelFormat + "\")",
                     {file, "/format", ""});
  const int version = member<int>(json, "version", "", file);
  if (version > kModelFormatVersion)
    throw UnsupportedVersionError(
        "model format version " + std::to_string(version) + " is newer than this build reads",
        {file, "/version", ""});
  ModelDocument m;
  m.id = member<std::string>(json, "id", "", file);
  m.name = optional_member<std::string>(json, "name", "", file, m.id);
  m.role = object_role_from_string(optional_member<std::string>(json, "role", "", file, "organ"));
  m.group = optional_member<std::string>(json, "group", "", file, "");
  primitive_from_json(member<nlohmann::json>(json, "primitive", "", file), file, m);
  if (json.contains("layering") && !json["layering"].is_null()) {
    const auto& l = json["layering"];
    ModelLayering layering;
    layering.layers.layers = member<int>(l, "layers", "/layering", file);
    layering.layers.thickness = member<double>(l, "thickness", "/layering", file);
    layering.layers.mode = layer_mode_from_string(
        optional_member<std::string>(l, "mode", "/layering", file, "offset"));
    const auto body = optional_member<std::string>(l, "body", "/layering", file, "tets");
    if (body != "tets" && body != "mass-spring")
      throw InputError("the body is \"tets\" or \"mass-spring\"", {file, "/layering/body", ""});
    layering.mass_spring = body == "mass-spring";
    layering.cell_size = optional_member<double>(l, "cell_size", "/layering", file, 0.0);
    m.layering = layering;
  }
  if (json.contains("material") && !json["material"].is_null())
    m.material = member<Material>(json, "material", "", file);
  const auto fixed =
      optional_member<nlohmann::json>(json, "fixed", "", file, nlohmann::json::array());
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    const std::string at = "/fixed/" + std::to_string(i);
    m.fixed.push_back(
        {member<Vec3>(fixed[i], "center", at, file), member<double>(fixed[i], "radius", at, file)});
  }
  const auto connections =
      optional_member<nlohmann::json>(json, "connections", "", file, nlohmann::json::array());
  for (std::size_t i = 0; i < connections.size(); ++i) {
    const std::string at = "/connections/" + std::to_string(i);
    m.connections.push_back(
        {member<std::string>(connections[i], "object", at, file),
         member<double>(connections[i], "distance", at, file),
         optional_member<double>(connections[i], "stiffness", at, file, 100.0)});
  }
  try {
    check_model(m);
  } catch (const UsageError& e) {
    throw ValidationError(e.reason(), {file, "", m.id});
  }
  return m;
}

}  // namespace viscera::core
