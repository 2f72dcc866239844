// Random numbers that are the same on every platform and library: std::mt19937_64 is fully
// specified by the standard, its distributions are not, so the conversions are written here.
#pragma once

#include "schemes/bodies.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace rotbench {

class RandomStream {
public:
    explicit RandomStream(std::uint64_t seed) : engine_(seed) {}
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1), 53 bits
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    std::size_t index(std::size_t n) { return static_cast<std::size_t>(uniform() * static_cast<double>(n)); }
    Vec3 unit_vector() {  // uniform on the sphere (Archimedes: z uniform in [-1, 1])
        const double z = uniform(-1.0, 1.0), phi = uniform(0.0, 2.0 * std::numbers::pi), s = std::sqrt(1.0 - z * z);
        return {s * std::cos(phi), s * std::sin(phi), z};
    }
    Quat rotation() {  // uniform on SO(3) (Shoemake)
        const double u1 = uniform(), u2 = uniform(0.0, 2.0 * std::numbers::pi), u3 = uniform(0.0, 2.0 * std::numbers::pi);
        const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
        return Quat(a * std::sin(u2), a * std::cos(u2), b * std::sin(u3), b * std::cos(u3)).normalized();
    }

private:
    std::mt19937_64 engine_;
};

}  // namespace rotbench
