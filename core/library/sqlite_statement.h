#pragma once
/// Thin RAII over the SQLite C API for the asset library: a prepared statement, a transaction
/// that rolls back unless committed, and SQLite result codes turned into typed errors naming
/// the database file (core/error.h). Internal to core/library.

#include <cstdint>
#include <filesystem>
#include <string>

struct sqlite3;
struct sqlite3_stmt;

namespace viscera::core {

/// An open connection and the file it is named by in errors.
struct SqliteDatabase {
  sqlite3* handle = nullptr;
  std::string file;

  /// Runs one or more statements without results. Throws as throw_sqlite_error.
  void execute(const std::string& sql) const;
};

/// Opens (creating) the database at `path` with a 10 s busy timeout. Throws OutputError naming
/// the file when it cannot be opened.
sqlite3* open_sqlite_database(const std::filesystem::path& path);

/// Throws for SQLite result `code`: InputError when the file is not a database or is corrupt,
/// OutputError otherwise (full disk, locked, read-only, …); the message is SQLite's.
[[noreturn]] void throw_sqlite_error(const SqliteDatabase& db, int code, const std::string& doing);

/// A prepared statement; columns and parameters count from 0 and 1 as in SQLite.
class SqliteStatement {
 public:
  SqliteStatement(const SqliteDatabase& db, const std::string& sql);
  ~SqliteStatement();
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;

  void bind(int index, const std::string& text);
  void bind(int index, std::int64_t value);
  void bind_blob(int index, const std::string& bytes);
  void bind_null(int index);
  /// Binds a named parameter such as ":type".
  void bind_named(const char* name, const std::string& text);

  /// Steps once: true when a row is ready, false when done. Throws as throw_sqlite_error.
  bool step();
  /// Makes the statement ready to run again (bindings are replaced by the next binds).
  void reset();

  bool is_null(int column) const;
  std::int64_t integer(int column) const;
  std::string text(int column) const;
  std::string blob(int column) const;

 private:
  const SqliteDatabase& db_;
  sqlite3_stmt* statement_ = nullptr;
};

/// BEGIN IMMEDIATE (a writer: takes the write lock at once, so reading the newest version and
/// inserting the next cannot interleave with another writer) or BEGIN (a reader's snapshot);
/// rolled back on destruction unless commit() was called.
class SqliteTransaction {
 public:
  explicit SqliteTransaction(const SqliteDatabase& db, bool write = true);
  ~SqliteTransaction();
  SqliteTransaction(const SqliteTransaction&) = delete;
  SqliteTransaction& operator=(const SqliteTransaction&) = delete;

  void commit();

 private:
  const SqliteDatabase& db_;
  bool open_ = true;
};

}  // namespace viscera::core
