#include "core/error.h"

namespace viscera::core {

std::string format_error_message(const std::string& message, const ErrorLocation& location) {
  std::string text;
  const auto append = [&text](const std::string& part) {
    if (part.empty()) return;
    text += part;
    text += ": ";
  };
  append(location.file);
  append(location.json_pointer);
  append(location.element);
  return text + message;
}

ExitCode exit_code_for(const std::exception& error) noexcept {
  if (dynamic_cast<const SimulationError*>(&error)) return ExitCode::SimulationFailed;
  if (dynamic_cast<const UsageError*>(&error)) return ExitCode::Usage;
  if (dynamic_cast<const ValidationError*>(&error)) return ExitCode::ValidationFailed;
  if (dynamic_cast<const InputError*>(&error)) return ExitCode::InvalidInput;
  return ExitCode::InternalError;
}

Error::Error(const std::string& message, ErrorLocation location)
    : std::runtime_error(format_error_message(message, location)),
      reason_(message),
      location_(std::move(location)) {}

namespace {

/// "body \"uterus\", node 12, step 40" from the parts that are known.
std::string simulation_place(const std::string& body, long long node, long long step) {
  std::string place;
  const auto add = [&place](const std::string& part) {
    place += (place.empty() ? "" : ", ") + part;
  };
  if (!body.empty()) add("body \"" + body + "\"");
  if (node >= 0) add("node " + std::to_string(node));
  if (step >= 0) add("step " + std::to_string(step));
  return place;
}

}  // namespace

SimulationError::SimulationError(const std::string& message, std::string body, long long node,
                                 long long step, std::string cause)
    : Error(message + (cause.empty() ? std::string() : "; likely cause: " + cause),
            {"", "", simulation_place(body, node, step)}),
      body_(std::move(body)),
      node_(node),
      step_(step),
      cause_(std::move(cause)) {}

}  // namespace viscera::core
