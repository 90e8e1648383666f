// Error types at the boundary of planarbench: each maps to one exit code of
// the command line (SPEC §5): InputError -> 2, EngineError -> 3.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pb {

// `text` on one printable line: each control character written as an escape,
// \0, \t, \n, \r or \xNN (a NUL would end the printed message, a newline
// would break the one-line rule); everything else as it is.
[[nodiscard]] std::string printable(std::string_view text);

// how much of a value a message echoes
inline constexpr std::size_t kEchoChars = 40;

// A value as a message echoes it: printable, between `quote`s, and when it
// has more than kEchoChars characters (UTF-8 code points), its first
// kEchoChars, "..." and its length: 'abc', or '1111...', 200 characters.
// quote '\0': no quotes (a key: abc, or 1111..., 200 characters); a key is
// cut at a larger `max_chars`, so that a long valid one is seen whole.
[[nodiscard]] std::string echo_value(std::string_view text, char quote = '\'',
                                     std::size_t max_chars = kEchoChars);

// Bad input: a file, a field or a command-line value. The message names the
// file, the line (when known), the field and what is allowed; it is made
// printable (control characters escaped), whatever the input held.
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
