#pragma once
/// The tissue materials shipped with Viscera (data/materials/tissues.json, compiled in):
/// myometrium, endometrium, myoma, ovary, fallopian tube, ligament, artery, vein, bowel, liver,
/// bladder and urethra. Each number carries its source — a published measurement (author, year,
/// journal) or an estimate saying what it was estimated from.
///
/// Each tissue's cubic σ(ε) = c1 ε + c3 ε³ (cubic_stress_fit.h) has c1 = the small-strain modulus
/// and c3 from one large-strain anchor: a tangent modulus E_t at a stress σ_a (then
/// c3 ε² = (E_t − c1)/3 and ε = σ_a / (c1 + c3 ε²)) or a stress σ_a at a strain ε_a (then
/// c3 = (σ_a − c1 ε_a) / ε_a³). The tearing threshold is the strain where the cubic reaches the
/// tensile strength, or is given; the Teschner constants follow from material_constants.h over
/// the catalogue's working strain; distance_damping = damping_time × distance_stiffness.

#include <string>
#include <utility>
#include <vector>

#include "core/scenario/material.h"

namespace viscera::core {

/// One shipped material with the provenance of its numbers.
struct ShippedMaterial {
  Material material;  ///< ready for a Scenario (id, name, constants, cubic, source summary)
  double poisson_ratio = 0.45;
  double working_strain = 0.3;
  /// (quantity, source sentence) in catalogue order: density, small-strain modulus, …
  std::vector<std::pair<std::string, std::string>> sources;
};

/// All shipped materials in catalogue order.
const std::vector<ShippedMaterial>& shipped_materials();

/// The shipped material `id`, or nullptr.
const ShippedMaterial* find_shipped_material(const std::string& id);

/// The shipped Material `id`. Throws UsageError naming the known ids otherwise.
Material shipped_material(const std::string& id);

/// Parses a material catalogue in the format of data/materials/tissues.json (format
/// "viscera-materials", version 1). Throws InputError (JSON syntax) or ValidationError naming
/// `what` and the JSON pointer of the offending member.
std::vector<ShippedMaterial> parse_material_catalogue(const std::string& json_text,
                                                      const std::string& what);

}  // namespace viscera::core
