#include "core/materials/stress_strain_csv.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

#include "core/error.h"

namespace viscera::core {
namespace {

/// How a column's values become SI.
struct ColumnUnit {
  enum class Quantity { Strain, Stress, Other } quantity = Quantity::Other;
  double scale = 1.0;   ///< multiply the field by this …
  double offset = 0.0;  ///< … then add this (stretch → strain)
};

std::string lower_trimmed(std::string s) {
  const auto not_space = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
  s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  for (auto& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

ColumnUnit unit_of_header(const std::string& raw) {
  // "stress [kPa]", "stress (kPa)", "stress_kpa" and "stress kpa" all name the same thing.
  std::string name;
  for (const char c : lower_trimmed(raw)) {
    if (c == '[' || c == ']' || c == '(' || c == ')' || c == ' ' || c == '-') {
      if (!name.empty() && name.back() != '_') name += '_';
    } else {
      name += c;
    }
  }
  while (!name.empty() && name.back() == '_')
    name.pop_back();
  using Q = ColumnUnit::Quantity;
  if (name == "strain" || name == "eps" || name == "epsilon") return {Q::Strain, 1.0, 0.0};
  if (name == "strain_percent" || name == "strain_%" || name == "strain_pct")
    return {Q::Strain, 0.01, 0.0};
  if (name == "stretch" || name == "lambda") return {Q::Strain, 1.0, -1.0};
  if (name == "stress" || name == "stress_pa" || name == "sigma") return {Q::Stress, 1.0, 0.0};
  if (name == "stress_kpa") return {Q::Stress, 1.0e3, 0.0};
  if (name == "stress_mpa" || name == "stress_n/mm2" || name == "stress_n/mm²")
    return {Q::Stress, 1.0e6, 0.0};
  return {};
}

std::vector<std::string> split_fields(const std::string& line) {
  const char separator = line.find(',') != std::string::npos   ? ','
                         : line.find(';') != std::string::npos ? ';'
                                                               : '\t';
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, separator))
    fields.push_back(field);
  if (!line.empty() && line.back() == separator) fields.emplace_back();
  return fields;
}

std::optional<double> parse_number(const std::string& field) {
  const std::string s = lower_trimmed(field);
  if (s.empty()) return std::nullopt;
  double value = 0.0;
  const char* begin = s.data();
  if (*begin == '+') ++begin;
  const auto [end, error] = std::from_chars(begin, s.data() + s.size(), value);
  if (error != std::errc() || end != s.data() + s.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

ErrorLocation at(const std::string& what, int line, int column) {
  return {
      what, "",
      "line " + std::to_string(line) + (column > 0 ? ", column " + std::to_string(column) : "")};
}

}  // namespace

StressStrainCurve parse_stress_strain_csv(const std::string& text, const std::string& what) {
  std::vector<ColumnUnit> columns = {{ColumnUnit::Quantity::Strain, 1.0, 0.0},
                                     {ColumnUnit::Quantity::Stress, 1.0, 0.0}};
  int strain_column = 0, stress_column = 1;
  bool header_seen = false, data_seen = false;
  StressStrainCurve curve;

  std::istringstream in(text);
  std::string line;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
      line.erase(0, 3);  // UTF-8 byte order mark
    const std::string trimmed = lower_trimmed(line);
    if (trimmed.empty() || trimmed.front() == '#') continue;
    const std::vector<std::string> fields = split_fields(line);

    if (!header_seen && !data_seen && !parse_number(fields.front())) {
      // The first line that does not start with a number is the header.
      header_seen = true;
      columns.clear();
      strain_column = stress_column = -1;
      for (std::size_t c = 0; c < fields.size(); ++c) {
        columns.push_back(unit_of_header(fields[c]));
        const auto q = columns.back().quantity;
        if (q == ColumnUnit::Quantity::Strain && strain_column < 0)
          strain_column = static_cast<int>(c);
        if (q == ColumnUnit::Quantity::Stress && stress_column < 0)
          stress_column = static_cast<int>(c);
      }
      if (strain_column < 0 || stress_column < 0) {
        throw InputError(std::string("the header names no ") +
                             (strain_column < 0 ? "strain" : "stress") +
                             " column (expected e.g. \"strain,stress_kpa\")",
                         at(what, line_number, 0));
      }
      continue;
    }

    data_seen = true;
    const int needed = std::max(strain_column, stress_column) + 1;
    if (static_cast<int>(fields.size()) < needed) {
      throw InputError("expected at least " + std::to_string(needed) + " fields, found " +
                           std::to_string(fields.size()),
                       at(what, line_number, 0));
    }
    double values[2] = {0.0, 0.0};
    const int wanted[2] = {strain_column, stress_column};
    for (int k = 0; k < 2; ++k) {
      const auto value = parse_number(fields[static_cast<std::size_t>(wanted[k])]);
      if (!value) {
        throw InputError("\"" + lower_trimmed(fields[static_cast<std::size_t>(wanted[k])]) +
                             "\" is not a finite number",
                         at(what, line_number, wanted[k] + 1));
      }
      const ColumnUnit& unit = columns[static_cast<std::size_t>(wanted[k])];
      values[k] = *value * unit.scale + unit.offset;
    }
    curve.strain.push_back(values[0]);
    curve.stress.push_back(values[1]);
  }
  if (curve.strain.size() < 4) {
    throw InputError("a stress-strain curve needs at least 4 samples, found " +
                         std::to_string(curve.strain.size()),
                     {what, "", ""});
  }
  return curve;
}

StressStrainCurve read_stress_strain_csv(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open the stress-strain file", {path.string(), "", ""});
  std::ostringstream text;
  text << in.rdbuf();
  return parse_stress_strain_csv(text.str(), path.string());
}

}  // namespace viscera::core
