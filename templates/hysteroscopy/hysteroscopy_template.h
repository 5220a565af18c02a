#pragma once
/// The `hysteroscopy` template (seed 000 §1.2, §2.1): a uterus with its cavity, cervical canal
/// and both tubal orifices, its wall in two layers (endometrium over myometrium, as tet labels
/// with a material each), the nodes near the cervix fixed, a CCO arterial tree in the wall,
/// textures for endometrium and myoma surfaces, landmarks that procedure tasks refer to, and a
/// random set of pathologies — submucosal, intramural and pedunculated myomas, endometrial
/// polyps and adhesions — each its own scene object attached to the wall.

#include "templates/template_catalog.h"

namespace viscera::templates {

/// Builds a virtual patient for diagnostic and operative hysteroscopy.
class HysteroscopyTemplate final : public ScenarioTemplate {
 public:
  /// The diagnostic patient ("hysteroscopy", procedure diagnostic-hysteroscopy), or with
  /// `polypectomy` the operative one ("hysteroscopy-polypectomy"): at least one polyp, a
  /// resectoscope, and the hysteroscopic-polypectomy procedure (issue 17 §5).
  explicit HysteroscopyTemplate(bool polypectomy = false) : polypectomy_(polypectomy) {}
  std::string name() const override {
    return polypectomy_ ? "hysteroscopy-polypectomy" : "hysteroscopy";
  }
  std::string description() const override;
  std::string version() const override { return "1"; }
  std::string procedure() const override { return "hysteroscopy"; }
  std::vector<TemplateParameter> parameters() const override;
  std::vector<core::VariabilityRule> default_variability() const override;
  core::Scenario build(const ParameterValues& parameters, std::uint64_t seed,
                       core::Progress& progress) const override;

 private:
  bool polypectomy_ = false;
};

}  // namespace viscera::templates
