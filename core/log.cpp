#include "core/log.h"

#include <spdlog/sinks/stdout_color_sinks.h>

namespace viscera::core {

std::shared_ptr<spdlog::logger> logger() {
  static std::shared_ptr<spdlog::logger> instance = [] {
    auto created = spdlog::stderr_color_mt("viscera");
    created->set_level(spdlog::level::warn);
    created->set_pattern("[%l] %v");
    return created;
  }();
  return instance;
}

void set_log_level(const std::string& level) {
  logger()->set_level(spdlog::level::from_str(level));
}

}  // namespace viscera::core
