// Error types at the boundary of planarbench: each maps to one exit code of
// the command line (SPEC §5): InputError -> 2, EngineError -> 3.
#pragma once

#include <stdexcept>
#include <string>

namespace pb {

// Bad input: a file, a field or a command-line value. The message names the
// file, the line (when known), the field and what is allowed.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string field, std::string what_is_wrong);
  // for errors without a file (command line): file is the option name
  explicit InputError(const std::string& message);

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] const std::string& field() const { return field_; }

 private:
  std::string file_;
  int line_ = 0;
  std::string field_;
};

// An engine failed to build a model or diverged while stepping.
class EngineError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Process exit codes (SPEC §5).
enum ExitCode : int {
  kExitOk = 0,
  kExitToleranceBreached = 1,
  kExitBadInput = 2,
  kExitEngineFailed = 3,
};

}  // namespace pb
