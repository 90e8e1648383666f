#include "planarbench/errors.hpp"

#include <fmt/format.h>

namespace pb {

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c != 0x7f) {
      out += ch;
    } else if (c == 0) {
      out += "\\0";
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else if (c == '\t') {
      out += "\\t";
    } else {
      out += fmt::format("\\x{:02x}", c);
    }
  }
  return out;
}

std::string echo_value(std::string_view text, char quote, std::size_t max_chars) {
  // characters are UTF-8 code points: every byte that does not continue one
  auto starts_char = [](char ch) { return (static_cast<unsigned char>(ch) & 0xC0) != 0x80; };
  std::size_t chars = 0;
  std::size_t cut = text.size();
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (!starts_char(text[i])) continue;
    if (chars == max_chars) cut = i;
    ++chars;
  }
  const std::string q = quote == '\0' ? std::string() : std::string(1, quote);
  if (chars <= max_chars) return q + printable(text) + q;
  return fmt::format("{}{}...{}, {} characters", q, printable(text.substr(0, cut)), q, chars);
}

namespace {
// FILE:LINE: FIELD: WHAT, the line and field left out when unknown
std::string format_input_error(const std::string& file, int line, const std::string& field,
                               const std::string& what) {
  std::string s = file;
  if (line > 0) s += fmt::format(":{}", line);
  if (!field.empty()) s += (s.empty() ? "" : ": ") + field;
  return printable(s + (s.empty() ? "" : ": ") + what);
}
}  // namespace

InputError::InputError(std::string file, int line, std::string field, std::string what_is_wrong)
    : std::runtime_error(format_input_error(file, line, field, what_is_wrong)),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)) {}

InputError::InputError(const std::string& message) : std::runtime_error(printable(message)) {}

}  // namespace pb
