#pragma once
/// Clinical display units for the studio's forms (issue 23 §1): the catalogue stores SI values
/// (templates::TemplateParameter), a clinician reads millimetres, degrees, millilitres and
/// kilopascals. A form shows `value × scale` with `suffix` and converts back by dividing.

#include <QString>
#include <string>

namespace viscera::studio {

/// How one SI unit is shown in a form.
struct ClinicalUnit {
  QString suffix;      ///< e.g. " mm", " °", "" for counts and ratios
  double scale = 1.0;  ///< shown value = SI value × scale
};

/// m → mm, rad → °, m^3 → ml, Pa → kPa, N/m and kg/m^3 as they are, "1" and "count" unitless.
ClinicalUnit clinical_unit(const std::string& si_unit);

/// "cervix_length" → "Cervix length": a parameter name as a form label.
QString readable_name(const std::string& name);

/// Decimals a spin box needs to show values of magnitude `smallest` (> 0) to 3 significant
/// digits, at least 0 and at most 6.
int display_decimals(double smallest);

}  // namespace viscera::studio
