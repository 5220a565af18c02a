#include "core/materials/shipped_materials.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/materials/cubic_stress_fit.h"
#include "core/materials/material_constants.h"
#include "core/materials/shipped_materials_data.h"

namespace viscera::core {
namespace {

/// Reads catalogue members with errors that name the file and the JSON pointer.
class CatalogueReader {
 public:
  explicit CatalogueReader(std::string what) : what_(std::move(what)) {}

  const nlohmann::json& member(const nlohmann::json& object, const std::string& key,
                               const std::string& pointer) const {
    const auto it = object.find(key);
    if (it == object.end()) fail("missing member \"" + key + "\"", pointer);
    return *it;
  }
  double number(const nlohmann::json& object, const std::string& key,
                const std::string& pointer) const {
    const auto& value = member(object, key, pointer);
    if (!value.is_number() || !std::isfinite(value.get<double>()))
      fail("must be a finite number", pointer + "/" + key);
    return value.get<double>();
  }
  double positive(const nlohmann::json& object, const std::string& key,
                  const std::string& pointer) const {
    const double value = number(object, key, pointer);
    if (!(value > 0.0)) fail("must be positive", pointer + "/" + key);
    return value;
  }
  std::string text(const nlohmann::json& object, const std::string& key,
                   const std::string& pointer) const {
    const auto& value = member(object, key, pointer);
    if (!value.is_string() || value.get<std::string>().empty())
      fail("must be a non-empty string", pointer + "/" + key);
    return value.get<std::string>();
  }
  /// A {"value": x, "source": "…"} quantity; records its source.
  double sourced(const nlohmann::json& object, const std::string& key, const std::string& pointer,
                 ShippedMaterial& into) const {
    const std::string at = pointer + "/" + key;
    const auto& quantity = member(object, key, pointer);
    const double value = positive(quantity, "value", at);
    into.sources.emplace_back(key, text(quantity, "source", at));
    return value;
  }
  [[noreturn]] void fail(const std::string& message, const std::string& pointer) const {
    throw ValidationError(message, {what_, pointer, ""});
  }

 private:
  std::string what_;
};

/// c3 of c1 ε + c3 ε³ from the stiffening anchor (see the header).
double cubic_coefficient(const CatalogueReader& r, const nlohmann::json& stiffening, double c1,
                         const std::string& at) {
  if (stiffening.contains("tangent_modulus")) {
    const double tangent = r.positive(stiffening, "tangent_modulus", at);
    const double stress = r.positive(stiffening, "at_stress", at);
    if (tangent < c1)
      r.fail("the tangent modulus is below the small-strain modulus", at + "/tangent_modulus");
    const double q = (tangent - c1) / 3.0;  // c3 ε²
    const double strain = stress / (c1 + q);
    return q / (strain * strain);
  }
  const double stress = r.positive(stiffening, "stress", at);
  const double strain = r.positive(stiffening, "at_strain", at);
  const double c3 = (stress - c1 * strain) / (strain * strain * strain);
  if (c3 < 0.0)
    r.fail("the anchor stress is below the small-strain line: the curve would soften",
           at + "/stress");
  return c3;
}

ShippedMaterial parse_material(const CatalogueReader& r, const nlohmann::json& m,
                               const std::string& at, double working_strain, double damping_time) {
  ShippedMaterial shipped;
  Material& material = shipped.material;
  material.id = r.text(m, "id", at);
  material.name = r.text(m, "name", at);
  material.density = r.sourced(m, "density", at, shipped);
  const double c1 = r.sourced(m, "small_strain_modulus", at, shipped);

  const auto& stiffening = r.member(m, "stiffening", at);
  const double c3 = cubic_coefficient(r, stiffening, c1, at + "/stiffening");
  shipped.sources.emplace_back("stiffening", r.text(stiffening, "source", at + "/stiffening"));
  const std::array<double, 4> cubic = {0.0, c1, 0.0, c3};

  double tearing_stress = 0.0;
  if (m.contains("tensile_strength")) {
    tearing_stress = r.sourced(m, "tensile_strength", at, shipped);
    material.tearing_threshold = strain_at_stress(cubic, tearing_stress, 10.0);
  } else {
    material.tearing_threshold = r.sourced(m, "tearing_strain", at, shipped);
    tearing_stress = cubic_stress(cubic, material.tearing_threshold);
  }
  const auto& plastic = r.member(m, "plastic_yield", at);
  material.plastic_yield = r.positive(plastic, "fraction_of_tearing", at + "/plastic_yield") *
                           material.tearing_threshold;
  shipped.sources.emplace_back("plastic_yield", r.text(plastic, "source", at + "/plastic_yield"));
  shipped.poisson_ratio = r.sourced(m, "poisson_ratio", at, shipped);
  shipped.working_strain = std::min(working_strain, material.tearing_threshold);

  // The curve holds the points the cubic was set from: the origin, the anchor and the tear.
  StressStrainCurve curve;
  const double anchor_strain =
      stiffening.contains("at_strain")
          ? stiffening.at("at_strain").get<double>()
          : strain_at_stress(cubic, stiffening.at("at_stress").get<double>(), 10.0);
  curve.strain = {0.0, anchor_strain, material.tearing_threshold};
  curve.stress = {0.0, cubic_stress(cubic, anchor_strain), tearing_stress};
  curve.cubic = {cubic.begin(), cubic.end()};
  material.stress_strain = curve;

  ElasticityOptions options;
  options.poisson_ratio = shipped.poisson_ratio;
  try {
    const TeschnerConstants k = teschner_constants(cubic, shipped.working_strain, options);
    material.distance_stiffness = k.distance_stiffness;
    material.volume_stiffness = k.volume_stiffness;
    material.area_stiffness = k.area_stiffness;
  } catch (const Error& e) {
    r.fail(e.reason(), at);
  }
  material.distance_damping = damping_time * material.distance_stiffness;

  for (const auto& [quantity, source] : shipped.sources) {
    material.source += (material.source.empty() ? "" : "; ") + quantity + ": " + source;
  }
  return shipped;
}

}  // namespace

std::vector<ShippedMaterial> parse_material_catalogue(const std::string& json_text,
                                                      const std::string& what) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(json_text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(std::string("not valid JSON: ") + e.what(), {what, "", ""});
  }
  const CatalogueReader r(what);
  if (!j.is_object() || j.value("format", "") != "viscera-materials")
    r.fail("format must be \"viscera-materials\"", "/format");
  if (j.value("version", 0) != 1)
    r.fail("unsupported version (this build reads version 1)", "/version");
  const double working_strain =
      r.positive(r.member(j, "working_strain", ""), "value", "/working_strain");
  const double damping_time = r.positive(r.member(j, "damping_time", ""), "value", "/damping_time");
  const auto& list = r.member(j, "materials", "");
  if (!list.is_array()) r.fail("must be an array", "/materials");

  std::vector<ShippedMaterial> materials;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = "/materials/" + std::to_string(i);
    materials.push_back(parse_material(r, list[i], at, working_strain, damping_time));
    for (std::size_t k = 0; k + 1 < materials.size(); ++k) {
      if (materials[k].material.id == materials.back().material.id)
        r.fail("duplicate id", at + "/id");
    }
  }
  return materials;
}

const std::vector<ShippedMaterial>& shipped_materials() {
  static const std::vector<ShippedMaterial> materials =
      parse_material_catalogue(shipped_materials_json(), "data/materials/tissues.json");
  return materials;
}

const ShippedMaterial* find_shipped_material(const std::string& id) {
  for (const auto& m : shipped_materials()) {
    if (m.material.id == id) return &m;
  }
  return nullptr;
}

Material shipped_material(const std::string& id) {
  if (const auto* m = find_shipped_material(id)) return m->material;
  std::string known;
  for (const auto& m : shipped_materials())
    known += (known.empty() ? "" : ", ") + m.material.id;
  throw UsageError("no shipped material \"" + id + "\" (known: " + known + ")");
}

}  // namespace viscera::core
