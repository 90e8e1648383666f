#include "planarbench/errors.hpp"

#include <fmt/format.h>

namespace pb {

namespace {
// FILE:LINE: FIELD: WHAT, the line and field left out when unknown
std::string format_input_error(const std::string& file, int line, const std::string& field,
                               const std::string& what) {
  std::string s = file;
  if (line > 0) s += fmt::format(":{}", line);
  if (!field.empty()) s += (s.empty() ? "" : ": ") + field;
  return s + (s.empty() ? "" : ": ") + what;
}
}  // namespace

InputError::InputError(std::string file, int line, std::string field, std::string what_is_wrong)
    : std::runtime_error(format_input_error(file, line, field, what_is_wrong)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)) {}

InputError::InputError(const std::string& message) : std::runtime_error(message) {}

}  // namespace pb
