/// libFuzzer's entry points for the clang fuzz build (`./dev.sh fuzz`): one program holds every
/// target and fuzzes the one $VISCERA_FUZZ_TARGET names.

#include <cstdio>
#include <cstdlib>
#include <string>

#include "tests/fuzz/fuzz_target.h"

namespace {
const viscera::fuzz::TargetFunction* chosen = nullptr;
}

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const char* name = std::getenv("VISCERA_FUZZ_TARGET");
  if (name && std::string(name) == "list") {  // ./dev.sh fuzz asks for the targets
    for (const auto& target : viscera::fuzz::target_names())
      std::printf("%s\n", target.c_str());
    std::exit(0);
  }
  chosen = name ? viscera::fuzz::find_target(name) : nullptr;
  if (!chosen) {
    std::fprintf(stderr, "viscera_fuzzer: set VISCERA_FUZZ_TARGET to one of:");
    for (const auto& target : viscera::fuzz::target_names())
      std::fprintf(stderr, " %s", target.c_str());
    std::fprintf(stderr, "\n");
    std::exit(2);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (*chosen)(viscera::fuzz::Bytes(data, size));
  return 0;
}
