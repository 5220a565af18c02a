#include "tests/importers/volume_fixtures.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "core/error.h"
#include "tests/support/command_runner.h"

namespace viscera::testing {

namespace fs = std::filesystem;

fs::path pydicom_file(const std::string& name) {
  const fs::path path = fs::path("/usr/lib/python3/dist-packages/pydicom/data/test_files") / name;
  if (!fs::exists(path)) ADD_FAILURE() << path << " is missing: install python3-pydicom (dev.sh)";
  return path;
}

fs::path nibabel_file(const std::string& name) {
  const fs::path path = fs::path("/usr/lib/python3/dist-packages/nibabel/tests/data") / name;
  if (!fs::exists(path)) ADD_FAILURE() << path << " is missing: install python3-nibabel (dev.sh)";
  return path;
}

nlohmann::json real_volume_headers(const fs::path& scratch) {
  const fs::path script = fs::path(VISCERA_SOURCE_DIR) / "tests/importers/volume_headers.py";
  const fs::path output = scratch / "headers.json";
  const std::string command = "/usr/bin/python3 " + shell_quote(script.string()) + " " +
                              shell_quote(cgal_images(scratch).string()) + " > " +
                              shell_quote(output.string());
  EXPECT_EQ(std::system(command.c_str()), 0)
      << command << " (needs python3-pydicom, python3-nibabel)";
  std::ifstream in(output);
  return nlohmann::json::parse(in, nullptr, false);
}

fs::path copy_to(const fs::path& source, const fs::path& dir, const std::string& name) {
  const fs::path target = dir / name;
  fs::copy_file(source, target, fs::copy_options::overwrite_existing);
  return target;
}

std::string volume_read_error(const std::filesystem::path& path,
                              const importers::VolumeReadOptions& options) {
  try {
    importers::read_volume(path, options);
  } catch (const core::InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace viscera::testing
