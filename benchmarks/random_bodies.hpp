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

// Body i of `from` as a scene of one body (the rest of its state from random_bodies(1)): how
// the tests step a body alone to compare it with the same body stepped in a batch.
inline Bodies body_alone(const Bodies& from, std::size_t i) {
    Bodies one = random_bodies(1);
    one.inertia.set(0, from.inertia[i]);
    one.orientation.set(0, from.orientation[i]);
    one.omega.set(0, from.omega[i]);
    one.torque.set(0, from.torque[i]);
    return one;
}

}  // namespace rotbench
