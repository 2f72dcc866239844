#include "harness/core/fnv1a.hpp"

#include <fmt/format.h>

namespace rotbench {

std::string Fnv1a::hex() const { return fmt::format("{:016x}", hash_); }

}  // namespace rotbench
