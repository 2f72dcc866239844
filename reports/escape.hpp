// Text made safe for the formats the CI outputs are read in, whatever it holds (a message
// may quote a plug-in's exception, hence any bytes).
#pragma once

#include <string>

namespace rotbench {

// Valid UTF-8: every malformed sequence replaced by U+FFFD.
std::string valid_utf8(const std::string& text);

// XML 1.0 character data or attribute value: valid UTF-8, markup escaped, and the characters
// XML 1.0 cannot hold at all (controls other than tab, line feed and carriage return; U+FFFE
// and U+FFFF) written as \uXXXX. In an attribute, tab and line breaks become references.
std::string xml_text(const std::string& text);
std::string xml_attribute(const std::string& text);

// A GitHub Actions workflow command's message (% and line breaks encoded, other control
// characters written as terminal_line writes them) and property value (also : and ,).
std::string actions_message(const std::string& text);
std::string actions_property(const std::string& text);

// One line for a terminal or a log a CI runner parses: valid UTF-8 with every control character
// (C0 with tab and line breaks, DEL, C1) written as \xNN, so that no text quoted in it starts a
// line of its own (a workflow command) or moves the cursor.
std::string terminal_line(const std::string& text);

// A Markdown table cell: one line, no unescaped '|'.
std::string markdown_cell(const std::string& text);

}  // namespace rotbench
