// FNV-1a, 64 bit: the fingerprint of a plan, a plug-in file and a reference cache key. Not a
// cryptographic hash: it tells a changed input from an unchanged one.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace rotbench {

class Fnv1a {
public:
    Fnv1a& feed(std::string_view text) {
        for (unsigned char c : text) hash_ = (hash_ ^ c) * 1099511628211ull;
        return *this;
    }
    std::uint64_t value() const { return hash_; }
    std::string hex() const;  // 16 hexadecimal digits

private:
    std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace rotbench
