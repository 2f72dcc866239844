// The state both speed tools step: N bodies with moments in [1, 3], random orientations,
// angular velocities and torques, from a fixed seed, so that the batched benchmark and the
// instruction counts see the same bodies on every run and for every scheme.
#pragma once

#include "schemes/bodies.hpp"

#include <random>

namespace rotbench {

inline Bodies random_bodies(std::size_t n) {
    Bodies b;
    b.resize(n);
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> u(-1.0, 1.0), moment(1.0, 3.0);
    for (std::size_t i = 0; i < n; ++i) {
        b.inertia.set(i, Vec3(moment(rng), moment(rng), moment(rng)));
        b.orientation.set(i, Quat(u(rng), u(rng), u(rng), u(rng)).normalized());
        b.omega.set(i, Vec3(u(rng), u(rng), u(rng)));
        b.torque.set(i, Vec3(u(rng), u(rng), u(rng)));
    }
    return b;
}

}  // namespace rotbench
