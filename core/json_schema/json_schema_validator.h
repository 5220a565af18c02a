#pragma once
/// A JSON Schema validator for the subset of draft 2020-12 that Viscera's schemas use:
/// type (one name or a list), properties, required, additionalProperties (bool or schema),
/// items, minItems, maxItems, enum, const, minimum, maximum, exclusiveMinimum,
/// exclusiveMaximum, minLength, pattern, $ref to "#/$defs/NAME", anyOf, oneOf.
/// Unknown keywords are ignored, as the specification asks.

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace viscera::core {

/// One schema violation: where in the instance, and what is wrong, in one sentence.
struct SchemaViolation {
  std::string pointer;  ///< RFC 6901 pointer into the instance, "" for the root
  std::string message;

  bool operator==(const SchemaViolation&) const = default;
};

/// Validates instances against one schema document.
class JsonSchemaValidator {
 public:
  /// Keeps a copy of `schema`; throws UsageError when a $ref inside it cannot be resolved.
  explicit JsonSchemaValidator(nlohmann::json schema);

  /// Every violation of `instance`, in document order; empty when it is valid.
  std::vector<SchemaViolation> validate(const nlohmann::json& instance) const;

 private:
  void check(const nlohmann::json& schema, const nlohmann::json& instance,
             const std::string& pointer, std::vector<SchemaViolation>& out) const;
  const nlohmann::json& resolve(const std::string& reference) const;
  void check_references(const nlohmann::json& schema) const;

  nlohmann::json schema_;
};

/// Escapes a member name for a JSON pointer ("~" → "~0", "/" → "~1").
std::string escape_pointer_token(const std::string& token);

}  // namespace viscera::core
