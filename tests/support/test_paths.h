#pragma once
/// Helpers shared by the test suites: a fresh scratch folder per test, file contents.

#include <filesystem>
#include <string>

namespace viscera::testing {

/// A new empty folder for the running test, under VISCERA_TEST_TMP or the system temp folder.
/// Named after the test suite and test so failures leave inspectable files.
std::filesystem::path scratch_dir();

/// The source tree root (for shipped data and docs/).
std::filesystem::path source_dir();

/// The whole content of a file as bytes (empty when it cannot be opened).
std::string file_bytes(const std::filesystem::path& path);

/// CGAL's image data (data/images of /usr/share/doc/libcgal-dev/data.tar.gz, Debian
/// libcgal-demo), extracted into `scratch` once.
std::filesystem::path cgal_images(const std::filesystem::path& scratch);

}  // namespace viscera::testing
