#pragma once
/// Fuzz targets for the readers a user can feed (issue 21 §1). Each target is one function from
/// bytes to nothing that must never crash, hang or throw anything but a typed core::Error: a
/// reader refuses bad bytes with core::InputError (or ValidationError, UsageError,
/// UnsupportedVersionError) and the CLI turns that into one sentence and exit code 3 or 4.
///
/// Sources register their targets at start-up (register_target). Built with clang and
/// -fsanitize=fuzzer (`./dev.sh fuzz`), libfuzzer_entry.cpp hands libFuzzer the target named by
/// $VISCERA_FUZZ_TARGET; in the normal build the replay program (fuzz_replay.cpp) runs a target
/// over the seed corpus and every regression file, as ctest tests.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace viscera::fuzz {

/// Bytes handed to a target.
using Bytes = std::span<const std::uint8_t>;
using TargetFunction = std::function<void(Bytes)>;

/// Registers `name` for the replay program; returns true (for a static initialiser).
bool register_target(const std::string& name, TargetFunction function);
/// The registered target `name`, or nullptr.
const TargetFunction* find_target(const std::string& name);
/// Names of every registered target, sorted.
std::vector<std::string> target_names();

/// Runs `read`, swallowing the typed errors a reader may throw for bad input. Any other
/// exception escapes: it is a finding (an untyped error a user would see as an internal error).
void expect_typed_errors(const std::function<void()>& read);

/// Writes `bytes` to a scratch file of this process named "input<extension>" (in $TMPDIR) and
/// returns its path; readers that dispatch on the extension see the format under test.
std::filesystem::path input_file(Bytes bytes, const std::string& extension);

/// A folder of this process holding `bytes` split at every occurrence of the four-byte marker
/// "\n--\n" into files named "<n><extension>" (a DICOM folder, a package folder); emptied first.
std::filesystem::path input_folder(Bytes bytes, const std::string& extension);

/// Same split, each chunk "relative/path\n" followed by the file's bytes (a package folder); a
/// path that is empty, absolute or climbs out with ".." is dropped with its chunk.
std::filesystem::path input_named_folder(Bytes bytes);

}  // namespace viscera::fuzz
