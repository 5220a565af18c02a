#include "tests/support/test_paths.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "tests/support/command_runner.h"

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

std::filesystem::path cgal_images(const std::filesystem::path& scratch) {
  namespace fs = std::filesystem;
  const fs::path archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  if (!fs::exists(archive))
    ADD_FAILURE() << archive << " is missing: install libcgal-demo (dev.sh)";
  const fs::path images = scratch / "cgal" / "data" / "images";
  if (!fs::exists(images)) {
    fs::create_directories(scratch / "cgal");
    const std::string command = "tar -xzf " + shell_quote(archive.string()) + " -C " +
                                shell_quote((scratch / "cgal").string()) + " data/images";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
  }
  return images;
}

}  // namespace viscera::testing
