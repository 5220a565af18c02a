#include "core/json_schema/json_schema_validator.h"

#include <cmath>
#include <regex>

#include "core/error.h"

namespace viscera::core {
namespace {

std::string type_of(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return "boolean";
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
      return "integer";
    case nlohmann::json::value_t::number_float:
      return "number";
    case nlohmann::json::value_t::string:
      return "string";
    case nlohmann::json::value_t::array:
      return "array";
    case nlohmann::json::value_t::object:
      return "object";
    default:
      return "unknown";
  }
}

bool has_type(const nlohmann::json& value, const std::string& type) {
  const std::string actual = type_of(value);
  if (type == actual) return true;
  if (type == "number") return actual == "integer";
  // A float with no fractional part is an integer in JSON Schema.
  if (type == "integer" && actual == "number") {
    const double d = value.get<double>();
    return std::isfinite(d) && d == std::floor(d);
  }
  return false;
}

std::string short_text(const nlohmann::json& value) {
  std::string text = value.dump();
  return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

}  // namespace

std::string escape_pointer_token(const std::string& token) {
  std::string escaped;
  for (const char c : token) {
    if (c == '~') {
      escaped += "~0";
    } else if (c == '/') {
      escaped += "~1";
    } else {
      escaped += c;
    }
  }
  return escaped;
}

JsonSchemaValidator::JsonSchemaValidator(nlohmann::json schema) : schema_(std::move(schema)) {
  check_references(schema_);
}

void JsonSchemaValidator::check_references(const nlohmann::json& schema) const {
  if (schema.is_object()) {
    if (const auto ref = schema.find("$ref"); ref != schema.end()) resolve(ref->get<std::string>());
    for (const auto& [key, value] : schema.items())
      check_references(value);
  } else if (schema.is_array()) {
    for (const auto& value : schema)
      check_references(value);
  }
}

const nlohmann::json& JsonSchemaValidator::resolve(const std::string& reference) const {
  static const std::string kPrefix = "#/$defs/";
  if (reference.rfind(kPrefix, 0) != 0) {
    throw UsageError("schema reference \"" + reference + "\" is not of the form #/$defs/NAME");
  }
  const auto defs = schema_.find("$defs");
  const std::string name = reference.substr(kPrefix.size());
  if (defs == schema_.end() || !defs->contains(name)) {
    throw UsageError("schema reference \"" + reference + "\" names no definition");
  }
  return (*defs)[name];
}

std::vector<SchemaViolation> JsonSchemaValidator::validate(const nlohmann::json& instance) const {
  std::vector<SchemaViolation> out;
  check(schema_, instance, "", out);
  return out;
}

void JsonSchemaValidator::check(const nlohmann::json& schema, const nlohmann::json& instance,
                                const std::string& pointer,
                                std::vector<SchemaViolation>& out) const {
  if (schema.is_boolean()) {
    if (!schema.get<bool>()) out.push_back({pointer, "no value is allowed here"});
    return;
  }
  if (const auto ref = schema.find("$ref"); ref != schema.end()) {
    check(resolve(ref->get<std::string>()), instance, pointer, out);
  }
  if (const auto type = schema.find("type"); type != schema.end()) {
    const std::vector<std::string> allowed =
        type->is_array() ? type->get<std::vector<std::string>>()
                         : std::vector<std::string>{type->get<std::string>()};
    bool matches = false;
    for (const auto& t : allowed)
      matches = matches || has_type(instance, t);
    if (!matches) {
      std::string expected;
      for (const auto& t : allowed)
        expected += (expected.empty() ? "" : " or ") + t;
      out.push_back({pointer, "expected " + expected + ", found " + type_of(instance)});
      return;  // the other keywords would only repeat the same mistake
    }
  }
  if (const auto values = schema.find("enum"); values != schema.end()) {
    bool found = false;
    for (const auto& v : *values)
      found = found || v == instance;
    if (!found)
      out.push_back(
          {pointer, "value " + short_text(instance) + " is not one of " + short_text(*values)});
  }
  if (const auto value = schema.find("const"); value != schema.end() && *value != instance) {
    out.push_back({pointer, "value must be " + short_text(*value)});
  }
  if (instance.is_number()) {
    const double x = instance.get<double>();
    if (const auto m = schema.find("minimum"); m != schema.end() && x < m->get<double>())
      out.push_back(
          {pointer, "value " + short_text(instance) + " is below the minimum " + short_text(*m)});
    if (const auto m = schema.find("maximum"); m != schema.end() && x > m->get<double>())
      out.push_back(
          {pointer, "value " + short_text(instance) + " is above the maximum " + short_text(*m)});
    if (const auto m = schema.find("exclusiveMinimum"); m != schema.end() && x <= m->get<double>())
      out.push_back(
          {pointer, "value " + short_text(instance) + " must be greater than " + short_text(*m)});
    if (const auto m = schema.find("exclusiveMaximum"); m != schema.end() && x >= m->get<double>())
      out.push_back(
          {pointer, "value " + short_text(instance) + " must be less than " + short_text(*m)});
  }
  if (instance.is_string()) {
    const auto& text = instance.get_ref<const std::string&>();
    if (const auto m = schema.find("minLength");
        m != schema.end() && text.size() < m->get<std::size_t>())
      out.push_back({pointer, "text is shorter than " + short_text(*m) + " characters"});
    if (const auto p = schema.find("pattern"); p != schema.end()) {
      if (!std::regex_search(text, std::regex(p->get<std::string>(), std::regex::ECMAScript))) {
        out.push_back(
            {pointer, "text " + short_text(instance) + " does not match " + p->get<std::string>()});
      }
    }
  }
  if (instance.is_array()) {
    if (const auto m = schema.find("minItems");
        m != schema.end() && instance.size() < m->get<std::size_t>())
      out.push_back({pointer, "needs at least " + short_text(*m) + " items, has " +
                                  std::to_string(instance.size())});
    if (const auto m = schema.find("maxItems");
        m != schema.end() && instance.size() > m->get<std::size_t>())
      out.push_back({pointer, "allows at most " + short_text(*m) + " items, has " +
                                  std::to_string(instance.size())});
    if (const auto items = schema.find("items"); items != schema.end()) {
      for (std::size_t i = 0; i < instance.size(); ++i)
        check(*items, instance[i], pointer + "/" + std::to_string(i), out);
    }
  }
  if (instance.is_object()) {
    if (const auto required = schema.find("required"); required != schema.end()) {
      for (const auto& name : *required) {
        if (!instance.contains(name.get<std::string>())) {
          out.push_back(
              {pointer, "required member \"" + name.get<std::string>() + "\" is missing"});
        }
      }
    }
    const auto properties = schema.find("properties");
    const auto additional = schema.find("additionalProperties");
    for (const auto& [key, value] : instance.items()) {
      const std::string child = pointer + "/" + escape_pointer_token(key);
      if (properties != schema.end() && properties->contains(key)) {
        check((*properties)[key], value, child, out);
      } else if (additional != schema.end()) {
        if (additional->is_boolean() && !additional->get<bool>()) {
          out.push_back({child, "member \"" + key + "\" is not allowed here"});
        } else if (additional->is_object()) {
          check(*additional, value, child, out);
        }
      }
    }
  }
  const auto count_matches = [&](const nlohmann::json& alternatives) {
    int matches = 0;
    for (const auto& alternative : alternatives) {
      std::vector<SchemaViolation> scratch;
      check(alternative, instance, pointer, scratch);
      if (scratch.empty()) ++matches;
    }
    return matches;
  };
  if (const auto any = schema.find("anyOf"); any != schema.end() && count_matches(*any) == 0) {
    out.push_back({pointer, "value matches none of the allowed forms"});
  }
  if (const auto one = schema.find("oneOf"); one != schema.end() && count_matches(*one) != 1) {
    out.push_back({pointer, "value must match exactly one of the allowed forms"});
  }
}

}  // namespace viscera::core
