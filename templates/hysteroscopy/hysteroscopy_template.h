#pragma once
/// The `hysteroscopy` template (seed 000 §1.2, §2.1): a uterus with its cavity, cervical canal
/// and both tubal orifices, its wall in two layers (endometrium over myometrium, as tet labels
/// with a material each), the nodes near the cervix fixed, a CCO arterial tree in the wall,
/// textures for endometrium and myoma surfaces, landmarks that procedure tasks refer to, and a
/// random set of pathologies — submucosal, intramural and pedunculated myomas, endometrial
/// polyps and adhesions — each its own scene object attached to the wall.

#include "templates/template_catalog.h"

namespace viscera::templates {

/// The procedure a hysteroscopy patient is made for.
enum class HysteroscopyVariant {
  diagnostic,   ///< "hysteroscopy": diagnostic-hysteroscopy, random pathologies
  polypectomy,  ///< "hysteroscopy-polypectomy": at least one polyp, a resectoscope
  myomectomy,   ///< "hysteroscopy-myomectomy": one or two submucosal myomas, a resectoscope
};

/// Builds a virtual patient for diagnostic and operative hysteroscopy.
class HysteroscopyTemplate final : public ScenarioTemplate {
 public:
  /// The diagnostic patient, or an operative one (issue 17 §5): the polypectomy patient has at
  /// least one polyp and the hysteroscopic-polypectomy procedure; the myomectomy patient has one
  /// or two sessile submucosal myomas (the first is "myoma-1"), no intramural or pedunculated
  /// ones, and the hysteroscopic-myomectomy procedure (the myoma shaved strip by strip).
  explicit HysteroscopyTemplate(HysteroscopyVariant variant = HysteroscopyVariant::diagnostic)
      : variant_(variant) {}
  std::string name() const override;
  std::string description() const override;
  std::string version() const override { return "1"; }
  std::string procedure() const override { return "hysteroscopy"; }
  std::vector<TemplateParameter> parameters() const override;
  std::vector<core::VariabilityRule> default_variability() const override;
  core::Scenario build(const ParameterValues& parameters, std::uint64_t seed,
                       core::Progress& progress) const override;

 private:
  HysteroscopyVariant variant_;
};

}  // namespace viscera::templates
