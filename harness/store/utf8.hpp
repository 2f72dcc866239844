// UTF-8 decoding for the readers that check text (TOML input) and the writers that escape it
// (reports' Markdown and SVG).
#pragma once

#include <cstddef>
#include <string_view>

namespace rotbench {

struct CodePoint {
    char32_t value = 0;
    std::size_t length = 0;  // bytes; 0 when the sequence is malformed
};

// The code point of the UTF-8 sequence at text[i] and its length, or length 0 when the
// sequence is malformed (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
CodePoint decode_utf8(std::string_view text, std::size_t i);

}  // namespace rotbench
