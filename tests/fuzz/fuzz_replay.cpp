/// Replays fuzz inputs through the registered targets in the normal (GCC) build, so the seed
/// corpus and every crash a fuzzer found stay regression tests in ctest:
///   viscera_fuzz_replay TARGET PATH…   (a PATH may be a folder: every file in it, sorted)
///   viscera_fuzz_replay --list
/// Exit 0 when every input was handled (read or refused with a typed error); a crash or an
/// untyped exception ends the program as it would end the user's. Each input is read under the
/// limits of replay_limits.h: an allocation over 2 GiB (here or in a reader's forked child) or
/// more than 20 s fails the run, naming the input.

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

#include "tests/fuzz/fuzz_target.h"
#include "tests/fuzz/replay_limits.h"

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--list") {
    for (const auto& name : viscera::fuzz::target_names())
      std::cout << name << "\n";
    return 0;
  }
  if (argc < 3) {
    std::cerr << "usage: viscera_fuzz_replay TARGET PATH... | --list\n";
    return 2;
  }
  const auto target = viscera::fuzz::find_target(argv[1]);
  if (!target) {
    std::cerr << "viscera_fuzz_replay: no fuzz target \"" << argv[1] << "\" (--list names them)\n";
    return 2;
  }
  std::vector<fs::path> inputs;
  for (int i = 2; i < argc; ++i) {
    const fs::path path = argv[i];
    if (fs::is_directory(path)) {
      for (const auto& entry : fs::directory_iterator(path))
        if (entry.is_regular_file()) inputs.push_back(entry.path());
    } else if (fs::is_regular_file(path)) {
      inputs.push_back(path);
    } else {
      std::cerr << "viscera_fuzz_replay: " << path.string() << " is missing\n";
      return 2;
    }
  }
  std::sort(inputs.begin(), inputs.end());
  const char* tmp = std::getenv("TMPDIR");
  const fs::path scratch =
      fs::path(tmp && *tmp ? tmp : "/tmp") / ("viscera-fuzz-replay-" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  viscera::fuzz::start_replay_limits(scratch);
  for (const auto& input : inputs) {
    std::ifstream in(input, std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    std::cout << argv[1] << ": " << input.string() << " (" << bytes.size() << " bytes)"
              << std::endl;
    viscera::fuzz::begin_input(input.string());
    (*target)(viscera::fuzz::Bytes(bytes.data(), bytes.size()));
    if (const std::string note = viscera::fuzz::end_input(); !note.empty()) {
      std::cerr << "viscera_fuzz_replay: " << note;
      return 1;
    }
  }
  fs::remove_all(scratch);
  std::cout << argv[1] << ": " << inputs.size() << " input(s) handled\n";
  return 0;
}
