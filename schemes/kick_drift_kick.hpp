// The angular-momentum splitting shared by the momentum-based schemes: a half kick of the
// world angular momentum with T^n, a free rotation of the orientation over dt at constant
// momentum, a half kick with T^{n+1}. It is the rotational counterpart of Velocity Verlet
// (Dullweber, Leimkuhler & McLachlan, J. Chem. Phys. 107:5840, 1997); the schemes built on
// it differ only in how they approximate the free rotation (the `Rotation` policy).
//
// The world angular momentum L is the variable kicked by the torque, and no free rotation
// changes it: every such scheme keeps L to round-off without torque. With one force
// evaluation per step the torque is averaged over the step (trapezoid), as the force is
// for the translation.
#pragma once

#include "schemes/quaternion.hpp"
#include "schemes/scheme.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rotbench {

// A Rotation policy is a type with
//   static Quat rotate(const RigidBody& start, const Vec3& momentum, double dt);
// which returns q^{n+1} for the free rotation from start.q at the constant world angular
// momentum `momentum` (= L^{n+1/2}); start also holds w^n and T^n.
template <class Rotation>
struct KickDriftKick {
    // L is the scheme's variable, kept from step to step: L^n after a step, L^{n+1/2} between
    // predict and correct. w is derived from it for the force model (and for output), and
    // taking L back from w at every step would cost two frame changes and add round-off.
    struct Memory {
        Vec3 momentum;  // world
    };

    static void start(const RigidBody& b, Memory& m) { m.momentum = momentum_from_omega(b.q, b.inertia, b.omega); }

    static void predict(RigidBody& b, Memory& m, double dt) {
        m.momentum += 0.5 * dt * b.torque;
        b.q = Rotation::rotate(b, m.momentum, dt);
        b.omega = omega_from_momentum(b.q, b.inertia, m.momentum);  // what the force model sees
    }

    static void correct(RigidBody& b, Memory& m, double dt) {
        m.momentum += 0.5 * dt * b.torque;
        b.omega = omega_from_momentum(b.q, b.inertia, m.momentum);
    }
};

// The implicit mid-step angular velocity of the time-reversible schemes: the fixed point of
//   w_mid = I(q_mid(w_mid))^-1 L,
// where midpoint(w) gives the orientation at the middle of the step rotated with w. Fixed-
// point iteration from the start-of-step value; it contracts by about dt |w| (I_max/I_min - 1)
// per pass. A step so large that it does not converge is a failure of the scheme there: it
// throws, and the harness records the run as failed.
template <class Midpoint>
Vec3 midpoint_angular_velocity(const RigidBody& start, const Vec3& momentum, Midpoint&& midpoint,
                               const char* scheme) {
    constexpr int max_iterations = 100;
    Vec3 omega = omega_from_momentum(start.q, start.inertia, momentum);
    double previous = INFINITY;
    for (int i = 0; i < max_iterations; ++i) {
        const Vec3 next = omega_from_momentum(midpoint(omega), start.inertia, momentum);
        const double change = (next - omega).norm(), scale = next.norm();
        omega = next;
        // Converged: within about four units of round-off of |w|, or, once below 1e-13 |w|,
        // no longer shrinking (the iteration then dithers between neighbouring doubles).
        if (change <= 1e-15 * scale || (change <= 1e-13 * scale && change >= previous)) return omega;
        previous = change;
    }
    throw std::runtime_error(std::string(scheme) + ": the mid-step angular velocity did not converge in " +
                             std::to_string(max_iterations) + " iterations (time step too large)");
}

}  // namespace rotbench
