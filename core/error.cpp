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
  if (dynamic_cast<const UsageError*>(&error)) return ExitCode::Usage;
  if (dynamic_cast<const ValidationError*>(&error)) return ExitCode::ValidationFailed;
  if (dynamic_cast<const InputError*>(&error)) return ExitCode::InvalidInput;
  return ExitCode::InternalError;
}

Error::Error(const std::string& message, ErrorLocation location)
    : std::runtime_error(format_error_message(message, location)),
      reason_(message),
      location_(std::move(location)) {}

}  // namespace viscera::core
