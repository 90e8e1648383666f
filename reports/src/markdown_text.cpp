#include "markdown_text.hpp"

#include <algorithm>

namespace pb::internal {

namespace {

bool word_char(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
         (static_cast<unsigned char>(ch) & 0x80) != 0;
}

}  // namespace

std::string md_text(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) {
      out += ' ';
    } else if (ch == '&') {
      out += "&amp;";
    } else if (ch == '<') {
      out += "&lt;";
    } else if (ch == '>') {
      out += "&gt;";
    } else if (ch == '\\' || ch == '`' || ch == '*' || ch == '[' || ch == ']' || ch == '|' ||
               ch == '~') {
      out += '\\';
      out += ch;
    } else if (ch == '_') {
      const bool inside_word = i > 0 && i + 1 < text.size() && word_char(text[i - 1]) &&
                               word_char(text[i + 1]);
      if (!inside_word) out += '\\';
      out += ch;
    } else {
      out += ch;
    }
  }
  return out;
}

// md_text at the start of a block (a paragraph, a list item): also no
// heading (#), list item (- + 1. 1)) or setext underline (=) of its own
std::string md_block(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  std::string out = md_text(text);
  if (out.empty()) return out;
  if (out.front() == '#' || out.front() == '-' || out.front() == '+' || out.front() == '=') {
    out.insert(0, 1, '\\');
    return out;
  }
  std::size_t digits = 0;
  while (digits < out.size() && out[digits] >= '0' && out[digits] <= '9') ++digits;
  if (digits > 0 && digits < out.size() && (out[digits] == '.' || out[digits] == ')')) {
    out.insert(digits, 1, '\\');
  }
  return out;
}

// text as a code span: fenced with one more backtick than its longest run
// of backticks (padded when it starts or ends with one), on one line
std::string md_code(std::string_view text) {
  std::string body;
  std::size_t run = 0;
  std::size_t longest = 0;
  for (const char ch : text) {
    body += static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f ? ' ' : ch;
    run = ch == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  const std::string fence(longest + 1, '`');
  const bool pad = !body.empty() && (body.front() == '`' || body.back() == '`');
  std::string out = fence;
  out.append(pad ? " " : "").append(body).append(pad ? " " : "").append(fence);
  return out;
}

}  // namespace pb::internal
