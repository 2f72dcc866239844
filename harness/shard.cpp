#include "harness/shard.hpp"

#include "harness/parse.hpp"
#include "harness/registry.hpp"

#include <charconv>
#include <cstdint>
#include <fmt/format.h>

namespace rotbench {

Shard parse_shard(const std::string& text) {
    const auto slash = text.find('/');
    const auto integer = [&](const std::string& part, int& out) {
        const auto [ptr, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
        return !part.empty() && ec == std::errc() && ptr == part.data() + part.size();
    };
    Shard s;
    if (slash == std::string::npos || !integer(text.substr(0, slash), s.index) || !integer(text.substr(slash + 1), s.count) ||
        s.count < 1 || s.index < 1 || s.index > s.count)
        throw InputError("--shard '" + text + "': expected K/N with integers 1 <= K <= N");
    return s;
}

std::vector<std::size_t> shard_indices(std::size_t plan_size, const Shard& shard) {
    std::vector<std::size_t> out;
    for (std::size_t i = static_cast<std::size_t>(shard.index - 1); i < plan_size; i += static_cast<std::size_t>(shard.count))
        out.push_back(i);
    return out;
}

std::string plan_id(const std::vector<RunSpec>& plan) {
    std::uint64_t h = 14695981039346656037ull;  // FNV-1a, 64 bit
    const auto feed = [&](const std::string& s) {
        for (unsigned char c : s) {
            h ^= c;
            h *= 1099511628211ull;
        }
    };
    for (const auto& r : plan) {
        feed(fmt::format("{}|{}|{:a}|{:a}|", r.scene, r.scheme, r.dt, r.t_end));
        for (const auto& [key, values] : r.params) {
            feed(key);
            for (double v : values) feed(fmt::format("={:a}", v));
        }
        feed("\n");
    }
    return fmt::format("{:016x}", h);
}

}  // namespace rotbench
