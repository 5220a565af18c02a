#include "core/scenario/scenario_json.h"

#include <charconv>
#include <cstdint>

#include "core/error.h"
#include "core/json_eigen.h"
#include "core/json_numbers.h"
#include "core/package/hydrometra_file.h"

namespace viscera::core {

// nlohmann::json conversions for every part, found by argument-dependent lookup. Optional
// members fall back to the struct's defaults so older manifests stay readable. Integers go
// through core/json_numbers.h.

void to_json(nlohmann::json& j, const StressStrainCurve& c) {
  j = {{"strain", c.strain},
       {"stress", c.stress},
       {"cubic", c.cubic},
       {"fit_rms_error", c.fit_rms_error},
       {"fit_max_error", c.fit_max_error}};
}
void from_json(const nlohmann::json& j, StressStrainCurve& c) {
  j.at("strain").get_to(c.strain);
  j.at("stress").get_to(c.stress);
  read_optional_member(j, "cubic", c.cubic);
  read_optional_member(j, "fit_rms_error", c.fit_rms_error);
  read_optional_member(j, "fit_max_error", c.fit_max_error);
}

void to_json(nlohmann::json& j, const Material& m) {
  j = {{"id", m.id},
       {"name", m.name},
       {"density", m.density},
       {"distance_stiffness", m.distance_stiffness},
       {"area_stiffness", m.area_stiffness},
       {"volume_stiffness", m.volume_stiffness},
       {"distance_damping", m.distance_damping},
       {"tearing_threshold", m.tearing_threshold},
       {"plastic_yield", m.plastic_yield},
       {"source", m.source}};
  if (m.stress_strain) j["stress_strain"] = *m.stress_strain;
}
void from_json(const nlohmann::json& j, Material& m) {
  j.at("id").get_to(m.id);
  read_optional_member(j, "name", m.name);
  read_optional_member(j, "density", m.density);
  read_optional_member(j, "distance_stiffness", m.distance_stiffness);
  read_optional_member(j, "area_stiffness", m.area_stiffness);
  read_optional_member(j, "volume_stiffness", m.volume_stiffness);
  read_optional_member(j, "distance_damping", m.distance_damping);
  read_optional_member(j, "tearing_threshold", m.tearing_threshold);
  read_optional_member(j, "plastic_yield", m.plastic_yield);
  read_optional_member(j, "source", m.source);
  if (const auto it = j.find("stress_strain"); it != j.end())
    m.stress_strain = it->get<StressStrainCurve>();
}

void to_json(nlohmann::json& j, const TextureSpec& t) {
  j = {{"id", t.id},       {"preset", t.preset}, {"seed", t.seed},
       {"width", t.width}, {"height", t.height}, {"maps", t.maps}};
}
void from_json(const nlohmann::json& j, TextureSpec& t) {
  j.at("id").get_to(t.id);
  read_optional_member(j, "preset", t.preset);
  read_optional_member(j, "seed", t.seed);
  read_optional_member(j, "width", t.width);
  read_optional_member(j, "height", t.height);
  read_optional_member(j, "maps", t.maps);
}

void to_json(nlohmann::json& j, const VesselSegment& s) {
  j = {{"id", s.id},         {"parent", s.parent}, {"proximal", s.proximal},
       {"distal", s.distal}, {"radius", s.radius}, {"flow", s.flow}};
}
void from_json(const nlohmann::json& j, VesselSegment& s) {
  read_member(j, "id", s.id);
  read_optional_member(j, "parent", s.parent);
  j.at("proximal").get_to(s.proximal);
  j.at("distal").get_to(s.distal);
  j.at("radius").get_to(s.radius);
  read_optional_member(j, "flow", s.flow);
}

void to_json(nlohmann::json& j, const VesselTree& t) {
  j = {{"id", t.id}, {"host_object", t.host_object}, {"kind", t.kind}, {"segments", t.segments}};
}
void from_json(const nlohmann::json& j, VesselTree& t) {
  j.at("id").get_to(t.id);
  read_optional_member(j, "host_object", t.host_object);
  read_optional_member(j, "kind", t.kind);
  read_optional_member(j, "segments", t.segments);
}

void to_json(nlohmann::json& j, const PulseSpec& p) {
  j = {{"vessel_tree", p.vessel_tree},
       {"heart_rate", p.heart_rate},
       {"pulse_velocity", p.pulse_velocity},
       {"wall_force", p.wall_force}};
}
void from_json(const nlohmann::json& j, PulseSpec& p) {
  read_optional_member(j, "vessel_tree", p.vessel_tree);
  read_optional_member(j, "heart_rate", p.heart_rate);
  read_optional_member(j, "pulse_velocity", p.pulse_velocity);
  read_optional_member(j, "wall_force", p.wall_force);
}

void to_json(nlohmann::json& j, const MotilitySpec& m) {
  j = {{"amplitude_mean", m.amplitude_mean},
       {"amplitude_variance", m.amplitude_variance},
       {"wave_speed", m.wave_speed},
       {"wave_direction", m.wave_direction},
       {"frequency", m.frequency},
       {"frequency_disturbance", m.frequency_disturbance},
       {"contraction_interval_mean", m.contraction_interval_mean},
       {"contraction_interval_variance", m.contraction_interval_variance}};
}
void from_json(const nlohmann::json& j, MotilitySpec& m) {
  read_optional_member(j, "amplitude_mean", m.amplitude_mean);
  read_optional_member(j, "amplitude_variance", m.amplitude_variance);
  read_optional_member(j, "wave_speed", m.wave_speed);
  read_optional_member(j, "wave_direction", m.wave_direction);
  read_optional_member(j, "frequency", m.frequency);
  read_optional_member(j, "frequency_disturbance", m.frequency_disturbance);
  read_optional_member(j, "contraction_interval_mean", m.contraction_interval_mean);
  read_optional_member(j, "contraction_interval_variance", m.contraction_interval_variance);
}

void to_json(nlohmann::json& j, const ActiveDeformation& a) {
  j = {{"id", a.id}, {"target_object", a.target_object}};
  if (const auto* pulse = std::get_if<PulseSpec>(&a.spec)) {
    j["type"] = "pulse";
    j["pulse"] = *pulse;
  } else {
    j["type"] = "motility";
    j["motility"] = std::get<MotilitySpec>(a.spec);
  }
}
void from_json(const nlohmann::json& j, ActiveDeformation& a) {
  j.at("id").get_to(a.id);
  read_optional_member(j, "target_object", a.target_object);
  const std::string type = j.at("type").get<std::string>();
  if (type == "pulse") {
    a.spec = j.value("pulse", nlohmann::json::object()).get<PulseSpec>();
  } else if (type == "motility") {
    a.spec = j.value("motility", nlohmann::json::object()).get<MotilitySpec>();
  } else {
    throw ValidationError("unknown active deformation type \"" + type + "\"", {"", "/type", ""});
  }
}

void to_json(nlohmann::json& j, const Pathology& p) {
  j = {{"id", p.id},         {"kind", p.kind},         {"host_object", p.host_object},
       {"object", p.object}, {"position", p.position}, {"size", p.size}};
}
void from_json(const nlohmann::json& j, Pathology& p) {
  j.at("id").get_to(p.id);
  j.at("kind").get_to(p.kind);
  read_optional_member(j, "host_object", p.host_object);
  read_optional_member(j, "object", p.object);
  read_optional_member(j, "position", p.position);
  read_optional_member(j, "size", p.size);
}

void to_json(nlohmann::json& j, const Connection& c) {
  j = {{"id", c.id},
       {"object_a", c.object_a},
       {"object_b", c.object_b},
       {"node_pairs", c.node_pairs},
       {"stiffness", c.stiffness}};
}
void from_json(const nlohmann::json& j, Connection& c) {
  j.at("id").get_to(c.id);
  j.at("object_a").get_to(c.object_a);
  j.at("object_b").get_to(c.object_b);
  read_optional_member(j, "node_pairs", c.node_pairs);
  read_optional_member(j, "stiffness", c.stiffness);
}

void to_json(nlohmann::json& j, const FluidSpec& f) {
  j = {{"enabled", f.enabled},
       {"medium", f.medium},
       {"inflow_pressure", f.inflow_pressure},
       {"outflow_pressure", f.outflow_pressure},
       {"overload_volume", f.overload_volume}};
}
void from_json(const nlohmann::json& j, FluidSpec& f) {
  read_optional_member(j, "enabled", f.enabled);
  read_optional_member(j, "medium", f.medium);
  read_optional_member(j, "inflow_pressure", f.inflow_pressure);
  read_optional_member(j, "outflow_pressure", f.outflow_pressure);
  read_optional_member(j, "overload_volume", f.overload_volume);
}

void to_json(nlohmann::json& j, const TaskSpec& t) {
  j = {{"id", t.id}, {"name", t.name}, {"kind", t.kind}, {"parameters", t.parameters}};
}
void from_json(const nlohmann::json& j, TaskSpec& t) {
  j.at("id").get_to(t.id);
  read_optional_member(j, "name", t.name);
  j.at("kind").get_to(t.kind);
  read_optional_member(j, "parameters", t.parameters);
}

void to_json(nlohmann::json& j, const SubstepSpec& s) {
  j = {{"id", s.id}, {"name", s.name}, {"tasks", s.tasks}};
}
void from_json(const nlohmann::json& j, SubstepSpec& s) {
  j.at("id").get_to(s.id);
  read_optional_member(j, "name", s.name);
  read_optional_member(j, "tasks", s.tasks);
}

void to_json(nlohmann::json& j, const StepSpec& s) {
  j = {{"id", s.id}, {"name", s.name}, {"substeps", s.substeps}};
}
void from_json(const nlohmann::json& j, StepSpec& s) {
  j.at("id").get_to(s.id);
  read_optional_member(j, "name", s.name);
  read_optional_member(j, "substeps", s.substeps);
}

void to_json(nlohmann::json& j, const InstrumentSpec& i) {
  j = {{"kind", i.kind},
       {"optics_angle", i.optics_angle},
       {"field_of_view", i.field_of_view},
       {"shaft_diameter", i.shaft_diameter},
       {"focus_distance", i.focus_distance},
       {"min_view_distance", i.min_view_distance},
       {"max_view_distance", i.max_view_distance}};
}
void from_json(const nlohmann::json& j, InstrumentSpec& i) {
  read_optional_member(j, "kind", i.kind);
  read_optional_member(j, "optics_angle", i.optics_angle);
  read_optional_member(j, "field_of_view", i.field_of_view);
  read_optional_member(j, "shaft_diameter", i.shaft_diameter);
  read_optional_member(j, "focus_distance", i.focus_distance);
  read_optional_member(j, "min_view_distance", i.min_view_distance);
  read_optional_member(j, "max_view_distance", i.max_view_distance);
}

void to_json(nlohmann::json& j, const SessionSpec& s) {
  j = {{"time_step", s.time_step}, {"duration_limit", s.duration_limit},
       {"gravity", s.gravity},     {"contact_stiffness", s.contact_stiffness},
       {"tasks", s.tasks},         {"metrics", s.metrics}};
  if (!s.procedure_definition.empty()) j["procedure_definition"] = s.procedure_definition;
  if (!(s.instrument == InstrumentSpec{})) j["instrument"] = s.instrument;
  if (!s.steps.empty()) j["steps"] = s.steps;
  if (s.force_warning != 0.0) j["force_warning"] = s.force_warning;
  if (s.perforation_depth != 0.0) j["perforation_depth"] = s.perforation_depth;
}
void from_json(const nlohmann::json& j, SessionSpec& s) {
  read_optional_member(j, "time_step", s.time_step);
  read_optional_member(j, "duration_limit", s.duration_limit);
  read_optional_member(j, "gravity", s.gravity);
  read_optional_member(j, "contact_stiffness", s.contact_stiffness);
  read_optional_member(j, "tasks", s.tasks);
  read_optional_member(j, "metrics", s.metrics);
  read_optional_member(j, "procedure_definition", s.procedure_definition);
  read_optional_member(j, "instrument", s.instrument);
  read_optional_member(j, "steps", s.steps);
  read_optional_member(j, "force_warning", s.force_warning);
  read_optional_member(j, "perforation_depth", s.perforation_depth);
}

void to_json(nlohmann::json& j, const VariabilityRule& r) {
  j = {{"parameter", r.parameter}, {"distribution", r.distribution}, {"arguments", r.arguments}};
}
void from_json(const nlohmann::json& j, VariabilityRule& r) {
  j.at("parameter").get_to(r.parameter);
  j.at("distribution").get_to(r.distribution);
  read_optional_member(j, "arguments", r.arguments);
}

void to_json(nlohmann::json& j, const Landmark& l) {
  j = {{"id", l.id},
       {"name", l.name},
       {"object", l.object},
       {"position", l.position},
       {"normal", l.normal}};
}
void from_json(const nlohmann::json& j, Landmark& l) {
  j.at("id").get_to(l.id);
  read_optional_member(j, "name", l.name);
  read_optional_member(j, "object", l.object);
  j.at("position").get_to(l.position);
  read_optional_member(j, "normal", l.normal);
}

void to_json(nlohmann::json& j, const CellTypeSpec& t) {
  j = {{"id", t.id},
       {"mass", t.mass},
       {"radius", t.radius},
       {"home_stiffness", t.home_stiffness},
       {"connection_stiffness", t.connection_stiffness},
       {"damping", t.damping},
       {"collision_efficiency", t.collision_efficiency},
       {"tear_strain", t.tear_strain},
       {"yield_strain", t.yield_strain}};
}
void from_json(const nlohmann::json& j, CellTypeSpec& t) {
  j.at("id").get_to(t.id);
  read_optional_member(j, "mass", t.mass);
  read_optional_member(j, "radius", t.radius);
  read_optional_member(j, "home_stiffness", t.home_stiffness);
  read_optional_member(j, "connection_stiffness", t.connection_stiffness);
  read_optional_member(j, "damping", t.damping);
  read_optional_member(j, "collision_efficiency", t.collision_efficiency);
  read_optional_member(j, "tear_strain", t.tear_strain);
  read_optional_member(j, "yield_strain", t.yield_strain);
}

void to_json(nlohmann::json& j, const CellTissueSpec& c) {
  j = {{"object", c.object},
       {"types", c.types},
       {"cell_types", c.cell_types},
       {"neighbour_radius", c.neighbour_radius},
       {"max_neighbours", c.max_neighbours},
       {"planar", c.planar}};
}
void from_json(const nlohmann::json& j, CellTissueSpec& c) {
  j.at("object").get_to(c.object);
  read_optional_member(j, "types", c.types);
  read_optional_member(j, "cell_types", c.cell_types);
  read_optional_member(j, "neighbour_radius", c.neighbour_radius);
  read_optional_member(j, "max_neighbours", c.max_neighbours);
  read_optional_member(j, "planar", c.planar);
}

void to_json(nlohmann::json& j, const UrethraLatticeSpec& u) {
  j = {{"object", u.object},
       {"curvature", u.curvature},
       {"length", u.length},
       {"radius", u.radius},
       {"points_per_section", u.points_per_section},
       {"sections", u.sections},
       {"endoscope_radius", u.endoscope_radius},
       {"spring_stiffness", u.spring_stiffness},
       {"friction", u.friction},
       {"viscous_friction", u.viscous_friction},
       {"break_force", u.break_force},
       {"break_torque", u.break_torque}};
}
void from_json(const nlohmann::json& j, UrethraLatticeSpec& u) {
  j.at("object").get_to(u.object);
  read_optional_member(j, "curvature", u.curvature);
  read_optional_member(j, "length", u.length);
  read_optional_member(j, "radius", u.radius);
  read_optional_member(j, "points_per_section", u.points_per_section);
  read_optional_member(j, "sections", u.sections);
  read_optional_member(j, "endoscope_radius", u.endoscope_radius);
  read_optional_member(j, "spring_stiffness", u.spring_stiffness);
  read_optional_member(j, "friction", u.friction);
  read_optional_member(j, "viscous_friction", u.viscous_friction);
  read_optional_member(j, "break_force", u.break_force);
  read_optional_member(j, "break_torque", u.break_torque);
}

void to_json(nlohmann::json& j, const Provenance& p) {
  j = {{"template", p.template_name},
       {"template_version", p.template_version},
       {"seed", p.seed},
       {"parameters", p.parameters},
       {"tool_versions", p.tool_versions}};
}
void from_json(const nlohmann::json& j, Provenance& p) {
  read_optional_member(j, "template", p.template_name);
  read_optional_member(j, "template_version", p.template_version);
  read_optional_member(j, "seed", p.seed);
  read_optional_member(j, "parameters", p.parameters);
  read_optional_member(j, "tool_versions", p.tool_versions);
}

void to_json(nlohmann::json& j, const Metadata& m) {
  j = {{"name", m.name}, {"description", m.description}, {"author", m.author}};
}
void from_json(const nlohmann::json& j, Metadata& m) {
  j.at("name").get_to(m.name);
  read_optional_member(j, "description", m.description);
  read_optional_member(j, "author", m.author);
}

std::string surface_file_of(const std::string& object_id) {
  return "objects/" + object_id + "/surface.vtp";
}
std::string body_file_of(const std::string& object_id) {
  return "objects/" + object_id + "/body.vtu";
}

nlohmann::json scenario_to_json(const Scenario& s) {
  nlohmann::json objects = nlohmann::json::array();
  for (const auto& o : s.objects) {
    nlohmann::json object = {{"id", o.id},
                             {"name", o.name},
                             {"role", to_string(o.role)},
                             {"material", o.material},
                             {"texture", o.texture},
                             {"group", o.group},
                             {"body_kind", to_string(o.body_kind)},
                             {"surface", surface_file_of(o.id)}};
    if (o.body_kind != BodyKind::None) object["body"] = body_file_of(o.id);
    if (!o.hydrometra.empty()) object["hydrometra"] = hydrometra_file_of(o.id);
    if (!o.layer_materials.empty()) {
      nlohmann::json layers = nlohmann::json::object();
      for (const auto& [label, material] : o.layer_materials)
        layers[std::to_string(label)] = material;
      object["layer_materials"] = layers;
    }
    objects.push_back(std::move(object));
  }
  return {{"metadata", s.metadata},
          {"procedure", s.procedure},
          {"objects", objects},
          {"materials", s.materials},
          {"textures", s.textures},
          {"vessel_trees", s.vessel_trees},
          {"active_deformations", s.active_deformations},
          {"pathologies", s.pathologies},
          {"connections", s.connections},
          {"fluid", s.fluid},
          {"session", s.session},
          {"variability", s.variability},
          {"landmarks", s.landmarks},
          {"cell_tissues", s.cell_tissues},
          {"urethra_lattices", s.urethra_lattices},
          {"provenance", s.provenance}};
}

namespace {

/// Converts member `key` of `j`, turning a conversion failure into a ValidationError whose
/// pointer names the member.
template <typename T>
void convert_member(const nlohmann::json& j, const char* key, T& value, const std::string& file,
                    const std::string& pointer) {
  const auto it = j.find(key);
  if (it == j.end()) return;
  try {
    convert_checked(*it, value, file, pointer + "/" + key);
  } catch (const nlohmann::json::exception& e) {
    throw ValidationError(std::string("cannot read: ") + e.what(), {file, pointer + "/" + key, ""});
  }
}

}  // namespace

Scenario scenario_from_json(const nlohmann::json& j, const std::string& file,
                            const std::string& pointer_prefix) {
  if (!j.is_object())
    throw ValidationError("scenario must be a JSON object", {file, pointer_prefix, ""});
  Scenario s;
  convert_member(j, "metadata", s.metadata, file, pointer_prefix);
  convert_member(j, "procedure", s.procedure, file, pointer_prefix);
  convert_member(j, "materials", s.materials, file, pointer_prefix);
  convert_member(j, "textures", s.textures, file, pointer_prefix);
  convert_member(j, "vessel_trees", s.vessel_trees, file, pointer_prefix);
  convert_member(j, "active_deformations", s.active_deformations, file, pointer_prefix);
  convert_member(j, "pathologies", s.pathologies, file, pointer_prefix);
  convert_member(j, "connections", s.connections, file, pointer_prefix);
  convert_member(j, "fluid", s.fluid, file, pointer_prefix);
  convert_member(j, "session", s.session, file, pointer_prefix);
  convert_member(j, "variability", s.variability, file, pointer_prefix);
  convert_member(j, "landmarks", s.landmarks, file, pointer_prefix);
  convert_member(j, "cell_tissues", s.cell_tissues, file, pointer_prefix);
  convert_member(j, "urethra_lattices", s.urethra_lattices, file, pointer_prefix);
  convert_member(j, "provenance", s.provenance, file, pointer_prefix);

  const auto objects = j.find("objects");
  if (objects == j.end()) return s;
  if (!objects->is_array())
    throw ValidationError("objects must be a JSON array", {file, pointer_prefix + "/objects", ""});
  for (std::size_t i = 0; i < objects->size(); ++i) {
    const auto& o = (*objects)[i];
    const std::string pointer = pointer_prefix + "/objects/" + std::to_string(i);
    SceneObject object;
    try {
      o.at("id").get_to(object.id);
      object.name = o.value("name", std::string());
      object.material = o.value("material", std::string());
      object.texture = o.value("texture", std::string());
      object.group = o.value("group", std::string());
      const nlohmann::json layers = o.value("layer_materials", nlohmann::json::object());
      for (const auto& [label, material] : layers.items()) {
        int layer = 0;
        const auto [end, status] =
            std::from_chars(label.data(), label.data() + label.size(), layer);
        if (status != std::errc() || end != label.data() + label.size()) {
          throw ValidationError("a layer label is a whole number, not \"" + label + "\"",
                                {file, pointer + "/layer_materials", ""});
        }
        object.layer_materials[layer] = material.get<std::string>();
      }
    } catch (const nlohmann::json::exception& e) {
      throw ValidationError(std::string("cannot read object: ") + e.what(), {file, pointer, ""});
    }
    try {
      object.role = object_role_from_string(o.value("role", std::string("organ")));
    } catch (const InputError& e) {
      throw ValidationError(e.reason(), {file, pointer + "/role", ""});
    }
    try {
      object.body_kind = body_kind_from_string(o.value("body_kind", std::string("none")));
    } catch (const InputError& e) {
      throw ValidationError(e.reason(), {file, pointer + "/body_kind", ""});
    }
    s.objects.push_back(std::move(object));
  }
  return s;
}

}  // namespace viscera::core
