#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace viscera::testing {

std::filesystem::path scratch_dir() {
  const char* root = std::getenv("VISCERA_TEST_TMP");
  std::filesystem::path base =
      root ? root : std::filesystem::temp_directory_path() / "viscera-tests";
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string name =
      info ? std::string(info->test_suite_name()) + "." + info->name() : "unnamed";
  const auto dir = base / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::filesystem::path source_dir() {
  return VISCERA_SOURCE_DIR;
}

std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace viscera::testing
