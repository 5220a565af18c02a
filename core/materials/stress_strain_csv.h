#pragma once
/// Reading a measured uniaxial stress-strain curve from CSV (seed 001 §3.2: "The stress-strain
/// curves for various organs have been recorded and approximated by polynomials third degree").
///
/// Format: one sample per line, fields separated by commas, semicolons or tabs; blank lines and
/// lines starting with '#' are skipped. An optional header line names the columns and their
/// units; without one the first column is strain (dimensionless) and the second stress in Pa.
///
/// | header name                                  | meaning                         |
/// | -------------------------------------------- | ------------------------------- |
/// | `strain`                                     | engineering strain, ε           |
/// | `strain_percent`, `strain [%]`, `strain_%`   | strain in percent               |
/// | `stretch`, `lambda`                          | stretch λ = 1 + ε               |
/// | `stress`, `stress_pa`, `stress [Pa]`         | engineering stress in Pa        |
/// | `stress_kpa`, `stress [kPa]`                 | stress in kPa                   |
/// | `stress_mpa`, `stress [MPa]`                 | stress in MPa                   |
///
/// Other columns (time, force, …) are ignored.

#include <filesystem>
#include <string>

#include "core/scenario/material.h"

namespace viscera::core {

/// The curve in `path` as strain (dimensionless) and stress (Pa), in file order. Throws
/// InputError naming the file, line and column for an unreadable file, a header without a
/// strain or a stress column, a field that is not a finite number, a row with too few fields,
/// or fewer than 4 samples (a cubic fit needs more samples than its 3 coefficients).
StressStrainCurve read_stress_strain_csv(const std::filesystem::path& path);

/// The same for CSV text; `what` names the source in errors.
StressStrainCurve parse_stress_strain_csv(const std::string& text, const std::string& what);

}  // namespace viscera::core
