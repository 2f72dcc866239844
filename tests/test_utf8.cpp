// The one UTF-8 decoder (harness/store/utf8.hpp) that the TOML reader and the reports' escaping
// share: the boundaries of RFC 3629's table, section 4, each side of every limit.
#include "harness/store/utf8.hpp"

#include <catch2/catch.hpp>
#include <string>

using namespace rotbench;

namespace {
CodePoint first(const std::string& bytes) { return decode_utf8(bytes, 0); }
}  // namespace

TEST_CASE("UTF-8: the first and last code point of each length decode, with their length in bytes") {
    const struct {
        std::string bytes;
        char32_t value;
        std::size_t length;
    } valid[] = {{"\x41", 0x41, 1},           {"\x7F", 0x7F, 1},           {"\xC2\x80", 0x80, 2},
                 {"\xDF\xBF", 0x7FF, 2},      {"\xE0\xA0\x80", 0x800, 3},  {"\xED\x9F\xBF", 0xD7FF, 3},
                 {"\xEE\x80\x80", 0xE000, 3}, {"\xEF\xBF\xBF", 0xFFFF, 3}, {"\xF0\x90\x80\x80", 0x10000, 4},
                 {"\xF4\x8F\xBF\xBF", 0x10FFFF, 4}};
    for (const auto& v : valid) {
        INFO("U+" << std::hex << static_cast<unsigned>(v.value));
        CHECK(first(v.bytes).value == v.value);
        CHECK(first(v.bytes).length == v.length);
        CHECK(decode_utf8("ab" + v.bytes, 2).length == v.length);  // at an offset, too
    }
}

TEST_CASE("UTF-8: overlong forms, surrogates, code points past U+10FFFF and cut sequences are malformed") {
    for (const std::string bytes : {"\xC0\x80", "\xC1\xBF",                  // overlong 2-byte forms
                                    "\xE0\x9F\xBF", "\xF0\x8F\xBF\xBF",      // overlong 3- and 4-byte forms
                                    "\xED\xA0\x80", "\xED\xBF\xBF",          // UTF-16 surrogates
                                    "\xF4\x90\x80\x80", "\xF5\x80\x80\x80",  // past U+10FFFF
                                    "\x80", "\xBF", "\xFE", "\xFF",          // not a first byte
                                    "\xC2", "\xE2\x82", "\xF0\x9F\x98",      // cut short by the end of the text
                                    "\xC2\x41", "\xE2\x28\xA1"}) {           // a continuation byte missing
        INFO(bytes.size() << " bytes starting " << std::hex << static_cast<unsigned>(static_cast<unsigned char>(bytes[0])));
        CHECK(first(bytes).length == 0);
    }
}
