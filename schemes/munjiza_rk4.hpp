// `munjiza_rk4`: Munjiza et al.'s Runge-Kutta average of the angular velocity, in the
// quaternion form of seed 000, eqs. 44-53.
//
// The angular momentum H (world) is the scheme's memory. Eq. 44 advances it with the
// torque at the start of the step, T^n, so the whole step happens in `predict`, and the
// force model sees w^{n+1}. `correct` has nothing left to do: T^{n+1} enters through
// eq. 44 of the next step.
//
// The kernel is a template on the map q(w, dt) of eq. 17 only so that a test can rerun it
// with the publication's own small-angle map, which explains Table 1's dt = 1e-6 entry.
#pragma once

#include "schemes/quaternion.hpp"
#include "schemes/scheme.hpp"

namespace rotbench {

struct ExactIncrement {
    static Quat map(const Vec3& omega, double dt) { return rotation_increment(omega, dt); }
};

template <class Increment = ExactIncrement>
struct MunjizaRk4 {
    struct Memory {
        Vec3 momentum;  // H, world frame
    };

    static void start(const RigidBody& b, Memory& m) {
        m.momentum = momentum_from_omega(b.q, b.inertia, b.omega);
    }

    static void predict(RigidBody& b, Memory& m, double dt) {
        m.momentum += dt * b.torque;                                            // eq. 44
        const Vec3& H = m.momentum;
        const Vec3 w1 = b.omega;                                                // eq. 46
        const Vec3 w2 = omega_from_momentum(Increment::map(w1, 0.5 * dt) * b.q, b.inertia, H);  // eq. 47
        const Vec3 w3 = omega_from_momentum(Increment::map(w2, 0.5 * dt) * b.q, b.inertia, H);  // eq. 48
        const Vec3 w4 = omega_from_momentum(Increment::map(w3, dt) * b.q, b.inertia, H);        // eq. 49
        const Vec3 w_mean = (w1 + 2.0 * w2 + 2.0 * w3 + w4) / 6.0;              // eq. 50
        b.q = Increment::map(w_mean, dt) * b.q;                                 // eqs. 51, 53
        b.omega = omega_from_momentum(b.q, b.inertia, H);                       // eq. 52
    }

    static void correct(RigidBody&, Memory&, double) {}
};

}  // namespace rotbench
