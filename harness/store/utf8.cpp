#include "harness/store/utf8.hpp"

namespace rotbench {

CodePoint decode_utf8(std::string_view text, std::size_t i) {
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

}  // namespace rotbench
