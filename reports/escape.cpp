#include "reports/escape.hpp"

#include "harness/store/utf8.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace {

template <class Each>
std::string map_code_points(const std::string& text, Each&& each) {
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
        const auto [cp, length] = decode_utf8(text, i);
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
    return map_code_points(text, [](std::string& out, char32_t cp, const std::string& bytes) {
        if (cp == '%') out += "%25";
        else if (cp == '\r') out += "%0D";
        else if (cp == '\n') out += "%0A";
        else if (cp < 0x20 || (cp >= 0x7F && cp < 0xA0)) out += fmt::format("\\x{:02X}", static_cast<unsigned>(cp));  // as terminal_line
        else out += bytes;
    });
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

std::string terminal_line(const std::string& text) {
    return map_code_points(text, [](std::string& out, char32_t cp, const std::string& bytes) {
        if (cp < 0x20 || (cp >= 0x7F && cp < 0xA0)) out += fmt::format("\\x{:02X}", static_cast<unsigned>(cp));
        else out += bytes;
    });
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
