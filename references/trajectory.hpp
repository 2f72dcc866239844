// A reference trajectory sampled at t_k = k dt, k = 0..N, for every body of a scene.
#pragma once

#include "references/dynamics.hpp"

#include <cstddef>
#include <vector>

namespace rotbench {

struct Trajectory {
    static constexpr std::size_t width = 13;  // qw qx qy qz | wx wy wz (world) | x y z | vx vy vz
    std::size_t bodies = 0;
    std::vector<double> values;               // [sample][body][width]

    std::size_t samples() const { return bodies ? values.size() / (bodies * width) : 0; }
    const double* at(std::size_t sample, std::size_t body) const { return &values[(sample * bodies + body) * width]; }
    ReferenceState state(std::size_t sample, std::size_t body) const {
        const double* v = at(sample, body);
        return {Quat(v[0], v[1], v[2], v[3]), Vec3(v[4], v[5], v[6])};
    }
    Vec3 position(std::size_t sample, std::size_t body) const { return Vec3(at(sample, body) + 7); }
    Vec3 velocity(std::size_t sample, std::size_t body) const { return Vec3(at(sample, body) + 10); }
};

}  // namespace rotbench
