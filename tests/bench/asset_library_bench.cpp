// Asset library writes and reads (issue 4, point 8). Peer in the same run: SQLite alone
// inserting and selecting the same blob with the same settings (WAL, synchronous FULL, one
// BEGIN IMMEDIATE transaction per write) — the difference is what the library adds: the
// payload's SHA-256, the version lookup, the tag rows, and the checksum test on every read.
#include <benchmark/benchmark.h>
#include <sqlite3.h>
#include <unistd.h>

#include <filesystem>

#include "core/library/asset_library.h"

namespace {

namespace fs = std::filesystem;

/// A database file of its own, removed with its WAL files when the benchmark ends (declared
/// before the connection, so it outlives it).
struct ScratchDatabase {
  fs::path file;
  explicit ScratchDatabase(const std::string& name)
      : file(fs::temp_directory_path() /
             ("viscera-bench-" + name + "-" + std::to_string(::getpid()) + ".sqlite")) {
    remove_files();
  }
  ~ScratchDatabase() { remove_files(); }
  void remove_files() const {
    for (const char* suffix : {"", "-wal", "-shm"})
      fs::remove(file.string() + suffix);
  }
};

std::string payload_of(std::size_t bytes) {
  std::string payload(bytes, '\0');
  std::uint32_t state = 12345;
  for (auto& b : payload) {
    state = state * 1664525u + 1013904223u;
    b = static_cast<char>(state >> 24);
  }
  return payload;
}

viscera::core::AssetEntry entry_of(std::size_t bytes) {
  viscera::core::AssetEntry entry;
  entry.summary.name = "organ";
  entry.summary.tags = {"bench", "uterus"};
  entry.summary.payload_format = "bin";
  entry.payload = payload_of(bytes);
  return entry;
}

void BM_AssetLibraryAdd(benchmark::State& state) {
  const ScratchDatabase scratch("library");
  viscera::core::AssetLibrary library(scratch.file);
  const auto entry = entry_of(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(library.add(entry));
  state.SetBytesProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_AssetLibraryAdd)->Arg(64 << 10)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

void BM_AssetLibraryGet(benchmark::State& state) {
  const ScratchDatabase scratch("library");
  viscera::core::AssetLibrary library(scratch.file);
  library.add(entry_of(static_cast<std::size_t>(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(library.get("organ"));
  state.SetBytesProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_AssetLibraryGet)->Arg(64 << 10)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

/// The peer: one table, one blob per row, the same pragmas and transactions.
struct RawDatabase {
  sqlite3* db = nullptr;
  explicit RawDatabase(const fs::path& file) {
    sqlite3_open(file.c_str(), &db);
    sqlite3_exec(db,
                 "PRAGMA journal_mode = WAL; PRAGMA synchronous = FULL; "
                 "CREATE TABLE blobs(id INTEGER PRIMARY KEY, payload BLOB NOT NULL)",
                 nullptr, nullptr, nullptr);
  }
  ~RawDatabase() { sqlite3_close(db); }
  void insert(const std::string& payload) {
    sqlite3_exec(db, "BEGIN IMMEDIATE", nullptr, nullptr, nullptr);
    sqlite3_stmt* s = nullptr;
    sqlite3_prepare_v2(db, "INSERT INTO blobs(payload) VALUES (?)", -1, &s, nullptr);
    sqlite3_bind_blob64(s, 1, payload.data(), payload.size(), SQLITE_TRANSIENT);
    sqlite3_step(s);
    sqlite3_finalize(s);
    sqlite3_exec(db, "COMMIT", nullptr, nullptr, nullptr);
  }
  std::string select() {
    sqlite3_stmt* s = nullptr;
    sqlite3_prepare_v2(db, "SELECT payload FROM blobs WHERE id = 1", -1, &s, nullptr);
    sqlite3_step(s);
    std::string payload(static_cast<const char*>(sqlite3_column_blob(s, 0)),
                        static_cast<std::size_t>(sqlite3_column_bytes(s, 0)));
    sqlite3_finalize(s);
    return payload;
  }
};

void BM_SqliteAloneInsert(benchmark::State& state) {
  const ScratchDatabase scratch("sqlite");
  RawDatabase raw(scratch.file);
  const std::string payload = payload_of(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state)
    raw.insert(payload);
  state.SetBytesProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_SqliteAloneInsert)->Arg(64 << 10)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

void BM_SqliteAloneSelect(benchmark::State& state) {
  const ScratchDatabase scratch("sqlite");
  RawDatabase raw(scratch.file);
  raw.insert(payload_of(static_cast<std::size_t>(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(raw.select());
  state.SetBytesProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_SqliteAloneSelect)->Arg(64 << 10)->Arg(1 << 20)->Unit(benchmark::kMillisecond);

}  // namespace
