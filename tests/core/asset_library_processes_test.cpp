// Processes sharing the asset library (issue 4, point 8). It survives a writer killed in the
// middle of a write: a child process adds entries in a loop, each one transaction, and reports
// every commit through a pipe; the parent kills it with SIGKILL at once or a little after a
// report, so the kill lands inside the next transaction, then checks the database. Two
// writers at once each get their own versions.
#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <set>
#include <thread>

#include "core/library/asset_library.h"
#include "core/sha256.h"
#include "tests/support/test_paths.h"

namespace viscera::core {
namespace {

namespace fs = std::filesystem;

constexpr int kTagsPerEntry = 3;

/// The payload of version `version` of entry `name`: 192 KiB of xorshift bytes, so each write
/// spans many pages and takes long enough to be interrupted.
std::string payload_of(const std::string& name, int version) {
  std::uint64_t state = 0x9E3779B97F4A7C15ull ^ (std::hash<std::string>{}(name) + version);
  std::string bytes(192 * 1024, '\0');
  for (auto& b : bytes) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    b = static_cast<char>(state >> 56);
  }
  return bytes;
}

/// Child: adds entries "organ-<i % 3>" forever, writing one byte to `report` after each commit.
[[noreturn]] void write_forever(const fs::path& file, int report) {
  try {
    AssetLibrary library(file);
    for (int i = 0;; ++i) {
      const std::string name = "organ-" + std::to_string(i % 3);
      AssetEntry entry;
      entry.summary.name = name;
      entry.summary.type = AssetType::Model;
      entry.summary.tags = {"a", "b", "tag-" + std::to_string(i)};
      entry.summary.provenance = "writer";
      entry.summary.payload_format = "bin";
      const auto existing = library.list(AssetType::Model, "", false);
      int next = 1;
      for (const auto& s : existing)
        if (s.name == name) next = s.version + 1;
      entry.payload = payload_of(name, next);
      library.add(entry);
      const char one = 1;
      if (::write(report, &one, 1) != 1) ::_exit(3);
    }
  } catch (...) {
    ::_exit(2);
  }
}

/// Every entry's tags are all there: the tags table agrees with the entry's tag_count.
int entries_with_missing_tags(const fs::path& file) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(file.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  sqlite3_stmt* statement = nullptr;
  sqlite3_prepare_v2(db,
                     "SELECT count(*) FROM entries e WHERE tag_count != "
                     "(SELECT count(*) FROM tags t WHERE t.entry_id = e.id)",
                     -1, &statement, nullptr);
  int missing = -1;
  if (sqlite3_step(statement) == SQLITE_ROW) missing = sqlite3_column_int(statement, 0);
  sqlite3_finalize(statement);
  sqlite3_close(db);
  return missing;
}

TEST(AssetLibraryProcesses, a_writer_killed_mid_write_leaves_every_committed_entry_whole) {
  const fs::path file = testing::scratch_dir() / "library.sqlite";
  int committed_total = 0;
  // Kill right after a commit report and at growing delays into the next transaction.
  const int delays_us[] = {0, 200, 700, 1500, 3000, 6000};
  for (int round = 0; round < 6; ++round) {
    int pipe_fds[2];
    ASSERT_EQ(::pipe(pipe_fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ::close(pipe_fds[0]);
      write_forever(file, pipe_fds[1]);
    }
    ::close(pipe_fds[1]);
    int reports = 0;
    char byte = 0;
    while (reports < 3 && ::read(pipe_fds[0], &byte, 1) == 1)
      ++reports;
    std::this_thread::sleep_for(std::chrono::microseconds(delays_us[round]));
    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    // Commits the parent had not read yet when the child died still count as committed.
    while (::read(pipe_fds[0], &byte, 1) == 1)
      ++reports;
    ::close(pipe_fds[0]);
    ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
        << "the writer ended by itself (status " << status << ") in round " << round;
    ASSERT_GE(reports, 3) << "round " << round;

    AssetLibrary library(file);
    EXPECT_EQ(library.integrity_check(), "ok") << "round " << round;
    const auto entries = library.list(std::nullopt, "", true);
    // Every reported commit is there; at most the one in flight when the kill came is extra
    // (its COMMIT was durable but the report not yet written).
    const int count = static_cast<int>(entries.size());
    EXPECT_GE(count, committed_total + reports) << "round " << round;
    EXPECT_LE(count, committed_total + reports + 1) << "round " << round;
    committed_total = count;
    for (const auto& summary : entries) {
      const AssetEntry entry = library.get(summary.name, summary.version);  // checks the sha
      EXPECT_EQ(entry.payload, payload_of(summary.name, summary.version))
          << summary.name << " v" << summary.version;
      EXPECT_EQ(summary.tags.size(), static_cast<std::size_t>(kTagsPerEntry));
    }
    // Versions of each name run 1, 2, … without a gap: no half-added version exists.
    std::map<std::string, int> highest;
    for (const auto& summary : entries) {
      EXPECT_EQ(summary.version, highest[summary.name] + 1) << summary.name;
      highest[summary.name] = summary.version;
    }
    EXPECT_EQ(entries_with_missing_tags(file), 0);
  }
  // The library is still writable after all the kills.
  AssetLibrary library(file);
  AssetEntry last;
  last.summary.name = "after";
  last.summary.payload_format = "bin";
  last.payload = "x";
  EXPECT_EQ(library.add(last).version, 1);
  EXPECT_EQ(library.integrity_check(), "ok");
}

TEST(AssetLibraryProcesses, two_writers_at_once_never_give_one_version_twice) {
  const fs::path file = testing::scratch_dir() / "library.sqlite";
  { AssetLibrary create(file); }  // both children open an existing library
  constexpr int kEach = 15;
  pid_t children[2];
  for (int c = 0; c < 2; ++c) {
    children[c] = ::fork();
    ASSERT_GE(children[c], 0);
    if (children[c] == 0) {
      try {
        AssetLibrary library(file);
        for (int i = 0; i < kEach; ++i) {
          AssetEntry entry;
          entry.summary.name = "shared";
          entry.summary.payload_format = "txt";
          entry.payload = "writer " + std::to_string(c) + " entry " + std::to_string(i);
          library.add(entry);
        }
      } catch (...) {
        ::_exit(2);
      }
      ::_exit(0);
    }
  }
  for (const pid_t child : children) {
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
  }
  AssetLibrary library(file);
  const auto entries = library.list(std::nullopt, "", true);
  ASSERT_EQ(entries.size(), 2u * kEach);
  std::set<std::string> payloads;
  for (int v = 1; v <= 2 * kEach; ++v) {
    EXPECT_EQ(entries[static_cast<std::size_t>(v - 1)].version, v);
    payloads.insert(library.get("shared", v).payload);
  }
  EXPECT_EQ(payloads.size(), 2u * kEach);  // every add kept, none overwritten
}

}  // namespace
}  // namespace viscera::core
