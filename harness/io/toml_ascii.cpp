#include "harness/io/toml_ascii.hpp"

#include "schemes/registry.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace {

// The code point of the UTF-8 sequence at text[i] and its length, or length 0 when the
// sequence is malformed (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
struct CodePoint {
    char32_t value = 0;
    std::size_t length = 0;
};

CodePoint decode(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) -> unsigned { return i + k < text.size() ? static_cast<unsigned char>(text[i + k]) : 0u; };
    const auto tail = [&](std::size_t n) {
        for (std::size_t k = 1; k <= n; ++k)
            if ((byte(k) & 0xC0u) != 0x80u) return false;
        return true;
    };
    const unsigned b0 = byte(0), b1 = byte(1);
    if (b0 < 0x80) return {b0, 1};
    if (b0 >= 0xC2 && b0 <= 0xDF && tail(1)) return {((b0 & 0x1Fu) << 6) | (b1 & 0x3Fu), 2};
    if (b0 >= 0xE0 && b0 <= 0xEF && tail(2) && !(b0 == 0xE0 && b1 < 0xA0) && !(b0 == 0xED && b1 > 0x9F))
        return {((b0 & 0x0Fu) << 12) | ((b1 & 0x3Fu) << 6) | (byte(2) & 0x3Fu), 3};
    if (b0 >= 0xF0 && b0 <= 0xF4 && tail(3) && !(b0 == 0xF0 && b1 < 0x90) && !(b0 == 0xF4 && b1 > 0x8F))
        return {((b0 & 0x07u) << 18) | ((b1 & 0x3Fu) << 12) | ((byte(2) & 0x3Fu) << 6) | (byte(3) & 0x3Fu), 4};
    return {0, 0};
}

enum class Context { bare, comment, basic, literal, multiline_basic, multiline_literal };

}  // namespace

std::string ascii_toml(std::string_view text, const std::string& name) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::string ascii;
    ascii.reserve(text.size());
    Context context = Context::bare;
    std::size_t line = 1, column = 1;
    // toml++ parses nesting by recursion: a file of 200 000 nested tables overflows its stack.
    // No configuration nests more than a few levels; 64 is refused before toml++ sees it.
    constexpr int max_depth = 64;
    int depth = 0;
    const auto fail = [&](const std::string& what) { throw InputError(fmt::format("{}:{}:{}: {}", name, line, column, what)); };
    const auto starts = [&](std::size_t i, std::string_view s) { return text.substr(i, s.size()) == s; };
    for (std::size_t i = 0; i < text.size();) {
        const CodePoint cp = decode(text, i);
        if (cp.length == 0) fail("the file is not valid UTF-8");
        std::size_t length = cp.length;  // bytes copied as they are
        if (cp.length > 1) {
            switch (context) {
                case Context::basic:
                case Context::multiline_basic:
                    ascii += cp.value <= 0xFFFF ? fmt::format("\\u{:04X}", static_cast<unsigned>(cp.value))
                                                : fmt::format("\\U{:08X}", static_cast<unsigned>(cp.value));
                    break;
                case Context::comment: ascii += '?'; break;
                case Context::literal:
                case Context::multiline_literal:
                    fail("a non-ASCII character in a literal string ('...'); write it in a basic string (\"...\")");
                    break;  // not reached: fail throws
                case Context::bare: fail("a non-ASCII character outside a string or comment");
            }
            i += cp.length;
            ++column;
            continue;
        }
        const char c = text[i];
        switch (context) {
            case Context::bare:
                if (c == '[' || c == '{') {
                    if (++depth > max_depth) fail(fmt::format("nested more than {} levels deep", max_depth));
                } else if ((c == ']' || c == '}') && depth > 0) {
                    --depth;
                }
                if (c == '#') context = Context::comment;
                else if (starts(i, "\"\"\"")) context = Context::multiline_basic, length = 3;
                else if (starts(i, "'''")) context = Context::multiline_literal, length = 3;
                else if (c == '"') context = Context::basic;
                else if (c == '\'') context = Context::literal;
                break;
            case Context::comment:
                if (c == '\n') context = Context::bare;
                break;
            case Context::basic:
                if (c == '\\' && i + 1 < text.size() && text[i + 1] >= 0 && text[i + 1] != '\n') length = 2;  // an escape
                else if (c == '"' || c == '\n') context = Context::bare;
                break;
            case Context::literal:
                if (c == '\'' || c == '\n') context = Context::bare;
                break;
            case Context::multiline_basic:
                if (c == '\\' && i + 1 < text.size() && text[i + 1] >= 0) length = 2;  // an escape or a line-ending backslash
                else if (starts(i, "\"\"\"")) context = Context::bare, length = 3;
                break;
            case Context::multiline_literal:
                if (starts(i, "'''")) context = Context::bare, length = 3;
                break;
        }
        for (std::size_t k = i; k < i + length; ++k) {
            ascii += text[k];
            if (text[k] == '\n') ++line, column = 1;
            else ++column;
        }
        i += length;
    }
    return ascii;
}

}  // namespace rotbench
