#pragma once
/// Putting a finished output in place so that a crash or `kill -9` at any moment leaves the
/// previous output whole under its name, or the new one, never a mix and never nothing.
/// Files are replaced by rename(2), folders by an atomic exchange (Linux renameat2 with
/// RENAME_EXCHANGE) after which the old folder is removed from its staging name.

#include <filesystem>

namespace viscera::core {

/// Moves `staged` (a finished file or folder beside `target`, on the same file system) to
/// `target`, replacing what is there in one atomic step. Throws core::OutputError naming
/// `target` when it cannot.
void replace_atomically(const std::filesystem::path& staged, const std::filesystem::path& target);

/// Swaps the two existing paths `a` and `b` (files or folders) in one atomic step. Throws
/// core::OutputError naming `b` when it cannot.
void exchange_atomically(const std::filesystem::path& a, const std::filesystem::path& b);

/// A hidden staging name beside `target`: ".<name><kind><pid>-<n>", unique in this process, e.g.
/// staging_sibling("out.vscz", ".tmp-") = ".out.vscz.tmp-4242-0".
std::filesystem::path staging_sibling(const std::filesystem::path& target, const char* kind);

/// Removes hidden staging siblings of `target` (names as staging_sibling() makes them) left by
/// processes that no longer run, e.g. killed in the middle of a write. Returns how many.
int remove_abandoned_staging(const std::filesystem::path& target);

}  // namespace viscera::core
