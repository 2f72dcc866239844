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
    static constexpr bool steps_packs = true;  // a template on the scalar: serves packs of bodies too
    template <class S>
    static QuatT<S> map(const Vec3T<S>& omega, double dt) { return rotation_increment<S>(omega, dt); }
};

template <class Increment = ExactIncrement, class S = double>
struct MunjizaRk4 {
    template <class T>
        requires(Increment::steps_packs)
    using rebind = MunjizaRk4<Increment, T>;
    struct Memory {
        Vec3T<S> momentum;  // H, world frame
    };

    static void start(const RigidBodyT<S>& b, Memory& m) {
        m.momentum = momentum_from_omega(b.q, b.inertia, b.omega);
    }

    static void predict(RigidBodyT<S>& b, Memory& m, double dt) {
        m.momentum += dt * b.torque;                                            // eq. 44
        const Vec3T<S>& H = m.momentum;
        const Vec3T<S> w1 = b.omega;                                            // eq. 46
        const Vec3T<S> w2 = omega_from_momentum(Increment::map(w1, 0.5 * dt) * b.q, b.inertia, H);  // eq. 47
        const Vec3T<S> w3 = omega_from_momentum(Increment::map(w2, 0.5 * dt) * b.q, b.inertia, H);  // eq. 48
        const Vec3T<S> w4 = omega_from_momentum(Increment::map(w3, dt) * b.q, b.inertia, H);        // eq. 49
        const Vec3T<S> w_mean = (w1 + 2.0 * w2 + 2.0 * w3 + w4) / 6.0;          // eq. 50
        b.q = Increment::map(w_mean, dt) * b.q;                                 // eqs. 51, 53
        b.omega = omega_from_momentum(b.q, b.inertia, H);                       // eq. 52
    }

    static void correct(RigidBodyT<S>&, Memory&, double) {}
};

}  // namespace rotbench
