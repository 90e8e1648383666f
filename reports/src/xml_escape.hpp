// Text into XML (the JUnit file of `check`, the report's SVG figures): the
// four markup characters of text and double-quoted attributes (& < > ") as
// entities, and what XML 1.0 cannot hold at all
// (control characters but tab, newline and carriage return: its Char
// production, https://www.w3.org/TR/xml/#charsets) as U+FFFD. Tab, newline
// and carriage return are written as character references, so that an
// attribute value keeps them (an attribute's literal newline is read back as
// a space). Issue 49: a `why` or a run's reason holding a control character
// made the JUnit file stop being XML.
#pragma once

#include <string>

namespace pb::internal {

[[nodiscard]] std::string xml_escape(const std::string& text);

}  // namespace pb::internal
