#include "harness/store/toml_ascii.hpp"

#include "harness/store/utf8.hpp"
#include "schemes/registry.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace {

enum class Context { bare, comment, basic, literal, multiline_basic, multiline_literal };

}  // namespace

std::string ascii_toml(std::string_view text, const std::string& name) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::string ascii;
    ascii.reserve(text.size());
    Context context = Context::bare;
    std::size_t line = 1, column = 1;
    // toml++ parses nesting by recursion: a file of 200 000 nested tables overflows its stack.
    // No configuration nests more than a few levels; 64 is refused before toml++ sees it. So
    // is a key of more than 64 dotted parts ([a.a.a...], a.a.a... = 1): a table each. Dots
    // are counted since the last line break, '=', ',', '{' or '[', so a value's (1.5) count once.
    constexpr int max_depth = 64;
    int depth = 0, dots = 0;
    const auto fail = [&](const std::string& what) { throw InputError(fmt::format("{}:{}:{}: {}", name, line, column, what)); };
    const auto starts = [&](std::size_t i, std::string_view s) { return text.substr(i, s.size()) == s; };
    for (std::size_t i = 0; i < text.size();) {
        const CodePoint cp = decode_utf8(text, i);
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
                if (c == '.' && ++dots > max_depth) fail(fmt::format("a key of more than {} dotted parts", max_depth));
                if (c == '=' || c == ',' || c == '{' || c == '[') dots = 0;
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
            if (text[k] == '\n') ++line, column = 1, dots = 0;
            else ++column;
        }
        i += length;
    }
    return ascii;
}

}  // namespace rotbench
