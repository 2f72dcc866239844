// TOML text made ASCII before toml++ reads it. Debian 12's toml++ (3.3.0) reaches
// __builtin_unreachable, undefined behaviour, when it asks whether some non-ASCII
// characters are whitespace (upstream marzer/tomlplusplus#190 and #295, fixed by PR #305;
// tests/fuzz found more such inputs, e.g. "d" then U+FE7F). So it never sees one:
//   - in a basic string ("..." or """...""") a non-ASCII character becomes its \uXXXX or
//     \UXXXXXXXX escape, which is the same string to TOML;
//   - in a comment it becomes '?', which changes nothing;
//   - anywhere else it is refused: TOML allows it only in strings and comments, and a
//     literal string ('...') has no escapes to write it with;
//   - malformed UTF-8 is refused (TOML text is UTF-8). A leading byte-order mark is dropped.
// Columns that toml++ reports after an escaped character on the same line are off by the
// escape's extra length; lines are exact.
#pragma once

#include <string>
#include <string_view>

namespace rotbench {

// The ASCII text, or InputError "name:line:column: ..." for what is refused.
std::string ascii_toml(std::string_view text, const std::string& name);

}  // namespace rotbench
