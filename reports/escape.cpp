#include "reports/escape.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace {

// The code point of the UTF-8 sequence at text[i] and its length, or length 0 when the
// sequence is malformed (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
std::pair<char32_t, std::size_t> decode(const std::string& text, std::size_t i) {
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

template <class Each>
std::string map_code_points(const std::string& text, Each&& each) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const auto [cp, length] = decode(text, i);
        if (length == 0) {
            out += "\xEF\xBF\xBD";  // U+FFFD
            ++i;
            continue;
        }
        each(out, cp, text.substr(i, length));
        i += length;
    }
    return out;
}

std::string xml(const std::string& text, bool attribute) {
    return map_code_points(text, [&](std::string& out, char32_t cp, const std::string& bytes) {
        switch (cp) {
            case '&': out += "&amp;"; return;
            case '<': out += "&lt;"; return;
            case '>': out += "&gt;"; return;
            case '"': out += "&quot;"; return;
            case '\'': out += "&apos;"; return;
            default: break;
        }
        if (attribute && (cp == '\t' || cp == '\n' || cp == '\r')) {
            out += fmt::format("&#{};", static_cast<unsigned>(cp));
        } else if ((cp < 0x20 && cp != '\t' && cp != '\n' && cp != '\r') || cp == 0xFFFE || cp == 0xFFFF) {
            out += fmt::format("\\u{:04X}", static_cast<unsigned>(cp));  // XML 1.0 cannot hold these at all
        } else {
            out += bytes;
        }
    });
}

}  // namespace

std::string valid_utf8(const std::string& text) {
    return map_code_points(text, [](std::string& out, char32_t, const std::string& bytes) { out += bytes; });
}

std::string xml_text(const std::string& text) { return xml(text, false); }
std::string xml_attribute(const std::string& text) { return xml(text, true); }

std::string actions_message(const std::string& text) {
    std::string out;
    for (char c : valid_utf8(text)) {
        if (c == '%') out += "%25";
        else if (c == '\r') out += "%0D";
        else if (c == '\n') out += "%0A";
        else out += c;
    }
    return out;
}

std::string actions_property(const std::string& text) {
    std::string out;
    for (char c : actions_message(text)) {
        if (c == ':') out += "%3A";
        else if (c == ',') out += "%2C";
        else out += c;
    }
    return out;
}

std::string markdown_cell(const std::string& text) {
    std::string out;
    for (char c : valid_utf8(text)) {
        if (c == '|') out += "\\|";
        else if (c == '\n' || c == '\r') out += ' ';
        else out += c;
    }
    return out;
}

}  // namespace rotbench
