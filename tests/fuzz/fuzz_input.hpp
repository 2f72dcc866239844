// Shared by the libFuzzer targets: the input as text, and the one outcome besides success
// that bad input may have. Anything else (another exception, a crash, a sanitizer report,
// a hang) is a bug that libFuzzer reports and keeps the input of.
#pragma once

#include "schemes/registry.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace rotbench::fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) { return {reinterpret_cast<const char*>(data), size}; }

template <class Parse>
void parse_or_input_error(Parse&& parse) {
    try {
        parse();
    } catch (const InputError& e) {
        if (std::string(e.what()).empty()) __builtin_trap();  // an error must say something
    }
}

}  // namespace rotbench::fuzz
