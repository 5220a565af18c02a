#pragma once
/// Typed errors of Viscera. Libraries throw these and never end the process; the CLI maps them
/// to exit codes (DESIGN.md §9) and the studio to a dialog. Every error carries where it
/// happened: a file, a JSON pointer inside it, or the id of an element.

#include <stdexcept>
#include <string>

namespace viscera::core {

/// Where an error happened. Any field may be empty.
struct ErrorLocation {
  std::string file;          ///< path of the file being read or written
  std::string json_pointer;  ///< RFC 6901 pointer inside a JSON document, e.g. "/objects/3"
  std::string element;       ///< id of a mesh element, object, or entry
};

/// Base of every Viscera error. what() is one sentence naming the file and place first.
class Error : public std::runtime_error {
 public:
  Error(const std::string& message, ErrorLocation location = {});

  /// The message without the location prefix.
  const std::string& reason() const noexcept { return reason_; }
  const ErrorLocation& location() const noexcept { return location_; }

 private:
  std::string reason_;
  ErrorLocation location_;
};

/// The input cannot be read or does not follow its format (CLI exit code 3).
class InputError : public Error {
 public:
  using Error::Error;
};

/// The input names a format version newer than this build understands (exit code 3).
class UnsupportedVersionError : public InputError {
 public:
  using InputError::InputError;
};

/// The input was read but fails its checks: schema, references, checksums (exit code 4).
class ValidationError : public Error {
 public:
  using Error::Error;
};

/// Writing an output failed; nothing partial was left behind (exit code 1).
class OutputError : public Error {
 public:
  using Error::Error;
};

/// A user or caller cancelled a long operation through its Progress object.
class CancelledError : public Error {
 public:
  using Error::Error;
};

/// A caller passed arguments outside the documented range (exit code 2 in the CLI).
class UsageError : public Error {
 public:
  using Error::Error;
};

/// The simulation reached a state it cannot go on from (exit code 5): the error names the body,
/// the node, the physics step and the likely cause, e.g. "non-finite state" or "inverted tets".
class SimulationError : public Error {
 public:
  /// `node` < 0 and `step` < 0 when unknown; `cause` is one clause ("the time step is too large
  /// for the material"), `message` says what was found.
  SimulationError(const std::string& message, std::string body, long long node, long long step,
                  std::string cause);

  const std::string& body() const noexcept { return body_; }
  long long node() const noexcept { return node_; }
  long long step() const noexcept { return step_; }
  const std::string& cause() const noexcept { return cause_; }

 private:
  std::string body_;
  long long node_ = -1, step_ = -1;
  std::string cause_;
};

/// Exit codes of the command-line contract (DESIGN.md §9).
enum class ExitCode : int {
  Success = 0,
  InternalError = 1,
  Usage = 2,
  InvalidInput = 3,
  ValidationFailed = 4,
  SimulationFailed = 5,  ///< a SimulationError: the session's physics cannot go on
};

/// The exit code a command-line tool returns for an exception that reached its main().
ExitCode exit_code_for(const std::exception& error) noexcept;

/// Formats "file: /pointer: element: message" from the non-empty parts.
std::string format_error_message(const std::string& message, const ErrorLocation& location);

}  // namespace viscera::core
