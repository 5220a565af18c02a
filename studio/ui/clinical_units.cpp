#include "studio/ui/clinical_units.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace viscera::studio {

ClinicalUnit clinical_unit(const std::string& si_unit) {
  if (si_unit == "m") return {QStringLiteral(" mm"), 1000.0};
  if (si_unit == "rad") return {QStringLiteral(" °"), 180.0 / std::numbers::pi};
  if (si_unit == "m^3" || si_unit == "m3") return {QStringLiteral(" ml"), 1.0e6};
  if (si_unit == "Pa") return {QStringLiteral(" kPa"), 1.0e-3};
  if (si_unit == "1/m") return {QStringLiteral(" 1/cm"), 1.0e-2};
  if (si_unit == "1" || si_unit == "count" || si_unit.empty()) return {QString(), 1.0};
  return {QStringLiteral(" ") + QString::fromStdString(si_unit), 1.0};
}

QString readable_name(const std::string& name) {
  QString text = QString::fromStdString(name).replace('_', ' ');
  if (!text.isEmpty()) text[0] = text[0].toUpper();
  return text;
}

int display_decimals(double smallest) {
  if (!(smallest > 0.0) || !std::isfinite(smallest)) return 2;
  return std::clamp(2 - static_cast<int>(std::floor(std::log10(smallest))), 0, 6);
}

}  // namespace viscera::studio
