// User text into Markdown (the report's report.md, `check --summary`):
// shown as written and nothing else, whatever it holds (issue 24; issue 49:
// a run's reason and a campaign axis name reached report.md and the
// summary as raw HTML).
#pragma once

#include <string>
#include <string_view>

namespace pb::internal {

// On one line (line breaks and other control characters to spaces), '<',
// '>' and '&' as HTML entities (no raw HTML), and with a backslash the
// punctuation that would make Markdown of it: \ ` * [ ] | ~, and '_' where
// it could open or close emphasis (not inside a word: falling_ball stays as
// it is). Safe in a table cell and inside a paragraph.
[[nodiscard]] std::string md_text(std::string_view text);

// md_text at the start of a block (a paragraph, a list item): also no
// heading (#), list item (- + 1. 1)) or setext underline (=) of its own.
[[nodiscard]] std::string md_block(std::string_view text);

// text as a code span: fenced with one more backtick than its longest run of
// backticks (padded when it starts or ends with one), on one line.
[[nodiscard]] std::string md_code(std::string_view text);

}  // namespace pb::internal
