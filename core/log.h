#pragma once
/// Logging through spdlog. Libraries log through viscera::core::logger(); applications choose
/// the level and the sink (stderr by default, so stdout stays clean for --json output).

#include <spdlog/spdlog.h>

#include <memory>

namespace viscera::core {

/// The shared "viscera" logger, created on first use and writing to stderr.
std::shared_ptr<spdlog::logger> logger();

/// Sets the level by name: "trace", "debug", "info", "warn", "error", "off".
void set_log_level(const std::string& level);

}  // namespace viscera::core
