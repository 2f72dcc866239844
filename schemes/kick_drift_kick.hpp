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
#include <concepts>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace rotbench {

// A Rotation policy is a type with
//   template <class S>
//   static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, double dt);
// which returns q^{n+1} for the free rotation from start.q at the constant world angular
// momentum `momentum` (= L^{n+1/2}); start also holds w^n and T^n. Written as a template on
// the scalar, the scheme steps packs of bodies (schemes/simd.hpp). A policy written for one
// body only, `static Quat rotate(const RigidBody&, const Vec3&, double)`, works as well; its
// scheme then steps one body at a time. A policy that changes frames at q^n more than once
// may take its body axes (body_axes) as well: rotate(start, momentum, axes, dt). One that
// returns a normalised q says so by deriving from UnitResult (a misspelt base does not
// compile, where a misspelt flag would silently take the other path).
template <class Rotation, class S = double>
concept RotationPolicy = requires(const RigidBodyT<S>& b, const Vec3T<S>& momentum, double dt) {
    { Rotation::rotate(b, momentum, dt) } -> std::same_as<QuatT<S>>;
} || requires(const RigidBodyT<S>& b, const Vec3T<S>& momentum, const BodyAxesT<S>& axes, double dt) {
    { Rotation::rotate(b, momentum, axes, dt) } -> std::same_as<QuatT<S>>;
};

struct UnitResult {};

#if ROTBENCH_SIMD
template <class Rotation>
concept RotatesPacks = RotationPolicy<Rotation, Pack>;
#else
template <class Rotation>
concept RotatesPacks = false;
#endif

template <class Rotation, class S = double>
    requires RotationPolicy<Rotation>
struct KickDriftKick {
    static_assert(!requires { Rotation::unit_result; }, "a policy that returns a unit q derives from UnitResult");
    template <class T>
        requires RotatesPacks<Rotation>
    using rebind = KickDriftKick<Rotation, T>;

    // L is the scheme's variable, kept from step to step: L^n after a step, L^{n+1/2} between
    // predict and correct. w is derived from it for the force model (and for output); taking
    // L back from w at every step would cost two frame changes and add round-off.
    struct Memory {
        Vec3T<S> momentum;  // world
    };

    static void start(const RigidBodyT<S>& b, Memory& m) { m.momentum = momentum_from_omega(b.q, b.inertia, b.omega); }

    static void predict(RigidBodyT<S>& b, Memory& m, double dt) {
        m.momentum += 0.5 * dt * b.torque;
        if constexpr (requires { Rotation::rotate(b, m.momentum, body_axes(b.q), dt); })
            b.q = Rotation::rotate(b, m.momentum, body_axes(b.q), dt);
        else b.q = Rotation::rotate(b, m.momentum, dt);
        b.omega = omega(b, m);  // what the force model sees
    }

    static void correct(RigidBodyT<S>& b, Memory& m, double dt) {
        m.momentum += 0.5 * dt * b.torque;
        b.omega = omega(b, m);
    }

private:
    // w = I(q)^-1 L. Of a normalised q, through its axes with no division by |q|^2 (shorter
    // than two quaternion rotations, which divide by it).
    ROTBENCH_INLINE static Vec3T<S> omega(const RigidBodyT<S>& b, const Memory& m) {
        if constexpr (std::is_base_of_v<UnitResult, Rotation>)
            return omega_from_momentum(body_axes<true>(b.q), b.inertia.cwiseInverse(), m.momentum);
        else return omega_from_momentum(b.q, b.inertia, m.momentum);
    }
};

template <class Rotation>
inline constexpr const char* kernel_family<KickDriftKick<Rotation>> = "kick_drift_kick";

// What a kick-drift-kick scheme claims by its structure, from what its rotation at constant L
// claims: the world angular momentum kept to round-off (no kick or free rotation changes it
// without torque); a rotation of order 2 or more, or the exact flow, stays second order between
// the trapezoidal kicks; a time-symmetric rotation makes the step symmetric, so time-reversible
// with bounded energy. The registration adds only what is the scheme's own.
struct RotationClaims {
    OrderClaim order;        // of the rotation at constant L; none when exact
    bool exact = false;      // the free flow itself
    bool symmetric = false;  // time-symmetric: rotating by -dt undoes rotating by dt
};
inline SchemeClaims kick_drift_kick_claims(const RotationClaims& rotation) {
    SchemeClaims c;
    c.without_torque = rotation.order;
    c.exact_without_torque = rotation.exact;
    if (rotation.exact || rotation.order.order >= 2)
        c.with_torque = {2, "trapezoidal kicks around a rotation of second order or better: second order"};
    c.conserves_momentum = true;
    c.bounded_energy = c.time_reversible = rotation.symmetric;
    return c;
}

// The implicit mid-step angular velocity of the time-reversible schemes: the fixed point of
//   w_mid = I(q_mid(w_mid))^-1 L,
// where midpoint(w) gives the orientation at the middle of the step rotated with w (any
// norm: its axes are divided by |q|^2), starting from w at q^n (axes: its body axes). Fixed-
// point iteration from the start-of-step value; it contracts by about dt |w| (I_max/I_min - 1)
// per pass. A step so large that it does not converge is a failure of the scheme there: it
// throws, and the harness records the run as failed. In a pack each body stops at its own
// pass, so that it gets the bits it gets alone.
template <class S, class Midpoint>
Vec3T<S> midpoint_angular_velocity(const RigidBodyT<S>& start, const Vec3T<S>& momentum, const BodyAxesT<S>& axes,
                                   Midpoint&& midpoint, const char* scheme) {
    constexpr int max_iterations = 100;
    const Vec3T<S> inverse_inertia = start.inertia.cwiseInverse();
    Vec3T<S> omega = omega_from_momentum(axes, inverse_inertia, momentum);
    S previous(INFINITY);
    auto iterating = all_true<S>();
    for (int i = 0; i < max_iterations; ++i) {
        const Vec3T<S> next = omega_from_momentum(body_axes(midpoint(omega)), inverse_inertia, momentum);
        const S change = (next - omega).norm(), scale = next.norm();
        omega = select(iterating, next, omega);
        // Converged: within about four units of round-off of |w|, or, once below 1e-13 |w|,
        // no longer shrinking (the iteration then dithers between neighbouring doubles).
        const auto converged = change <= 1e-15 * scale || (change <= 1e-13 * scale && change >= previous);
        previous = select(iterating, change, previous);
        iterating = iterating && !converged;
        if (!any_lane(iterating)) return omega;
    }
    throw std::runtime_error(std::string(scheme) + ": the mid-step angular velocity did not converge in " +
                             std::to_string(max_iterations) + " iterations (time step too large)");
}

#if ROTBENCH_SIMD
// A rotation computed one body at a time by the policy's double code, for maths that a pack
// cannot step together (exact_splitting's closed form branches on each body's motion).
template <class OneBody>
QuatT<Pack> each_body(const RigidBodyT<Pack>& start, const Vec3T<Pack>& momentum, OneBody&& rotate) {
    constexpr int count = 16;
    alignas(Pack::arch_type::alignment()) double in[count][Pack::size], out[4][Pack::size];
    const Pack* fields[count] = {&start.inertia.x(), &start.inertia.y(), &start.inertia.z(), &start.q.w(),
                                 &start.q.x(),       &start.q.y(),       &start.q.z(),       &start.omega.x(),
                                 &start.omega.y(),   &start.omega.z(),   &start.torque.x(),  &start.torque.y(),
                                 &start.torque.z(),  &momentum.x(),      &momentum.y(),      &momentum.z()};
    for (int f = 0; f < count; ++f) fields[f]->store_aligned(in[f]);
    for (std::size_t i = 0; i < Pack::size; ++i) {
        const RigidBody body{Vec3(in[0][i], in[1][i], in[2][i]), Quat(in[3][i], in[4][i], in[5][i], in[6][i]),
                             Vec3(in[7][i], in[8][i], in[9][i]), Vec3(in[10][i], in[11][i], in[12][i])};
        const Quat q = rotate(body, Vec3(in[13][i], in[14][i], in[15][i]));
        out[0][i] = q.w(), out[1][i] = q.x(), out[2][i] = q.y(), out[3][i] = q.z();
    }
    return QuatT<Pack>(Pack::load_aligned(out[0]), Pack::load_aligned(out[1]), Pack::load_aligned(out[2]),
                       Pack::load_aligned(out[3]));
}
#endif

}  // namespace rotbench
