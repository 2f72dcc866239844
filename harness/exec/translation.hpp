// Velocity Verlet for the translation of every body (seed eqs. 18-24). Shared by all
// rotation schemes, as in the seed, and run by the harness around each scheme's phases.
#pragma once

#include "schemes/bodies.hpp"

namespace rotbench {

// v += dt/2 F/m for body i: the half kick of eqs. 20 and 24.
inline void half_kick(Bodies& b, std::size_t i, double dt) {
    const double kick = 0.5 * dt / b.mass[i];
    b.velocity.x[i] += kick * b.force.x[i];
    b.velocity.y[i] += kick * b.force.y[i];
    b.velocity.z[i] += kick * b.force.z[i];
}

// Eqs. 20-21: half kick with F^n, then drift with the half-step velocity, body by body in
// one loop (it runs at every step of every run).
inline void translation_predict(Bodies& b, double dt) {
    for (std::size_t i = 0; i < b.size(); ++i) {
        half_kick(b, i, dt);
        b.position.x[i] += dt * b.velocity.x[i];
        b.position.y[i] += dt * b.velocity.y[i];
        b.position.z[i] += dt * b.velocity.z[i];
    }
}

// Eqs. 23-24: half kick with the force estimated at the new position.
inline void translation_correct(Bodies& b, double dt) {
    for (std::size_t i = 0; i < b.size(); ++i) half_kick(b, i, dt);
}

}  // namespace rotbench
