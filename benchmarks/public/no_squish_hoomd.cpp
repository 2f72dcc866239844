// `no_squish__hoomd`: NO_SQUISH as HOOMD-blue's TwoStepNVE steps an anisotropic particle
// (integrateStepOne/Two: torque taken to the body frame by a quaternion rotation, kicks of the
// conjugate quaternion momentum p += dt q (0, T'), free rotors 3, 2, 1, 2, 3 with libm's sin
// and cos, each skipped for a zero moment, and q renormalised by 1/sqrt once per step), written
// anew for the cost table's side-by-side comparison with rotbench's `no_squish`. The same map
// in exact arithmetic. HOOMD computes no angular velocity in its integrator (its forces depend
// on the orientation only); the harness's force model needs one, so w is taken from p as
// HOOMD's thermodynamics does: L' = 1/2 vec(q* p), w = q (L'/I) q*.
#include "benchmarks/public/no_squish_common.hpp"
#include "benchmarks/public/plain_arrays.hpp"

#include <cmath>

namespace rotbench {
namespace {

using public_codes::dot3, public_codes::normalise, public_codes::permute, public_codes::unpack;

// HOOMD's vec3 and quat arithmetic (VectorMath.h) on plain arrays: q = (s, v) as w, x, y, z.
// rotate(q, a) = (s^2 - v.v) a + 2 s (v x a) + 2 (v.a) v; `sign` -1 rotates by conj(q).
void rotate(const double q[4], double sign, const double a[3], double out[3]) {
    const double s = q[0], v[3] = {sign * q[1], sign * q[2], sign * q[3]};
    const double c[3] = {v[1] * a[2] - v[2] * a[1], v[2] * a[0] - v[0] * a[2], v[0] * a[1] - v[1] * a[0]};
    const double scale = s * s - dot3(v, v), along = 2.0 * dot3(v, a);
    for (int i = 0; i < 3; ++i) out[i] = scale * a[i] + 2.0 * s * c[i] + along * v[i];
}

// q (0, t) = (-v.t, s t + v x t): HOOMD's quat * vec3.
void times_vector(const double q[4], const double t[3], double out[4]) {
    const double v[3] = {q[1], q[2], q[3]};
    out[0] = -dot3(v, t);
    out[1] = q[0] * t[0] + (v[1] * t[2] - v[2] * t[1]);
    out[2] = q[0] * t[1] + (v[2] * t[0] - v[0] * t[2]);
    out[3] = q[0] * t[2] + (v[0] * t[1] - v[1] * t[0]);
}

struct NoSquishHoomd {
    struct Memory {
        double p[4];  // conjugate quaternion momentum, 2 q (0, L')
    };

    // p += dt q (0, T'), with T' = rotate(conj(q), T) and no torque about an axis of zero moment.
    // (HOOMD compares the moments with its EPSILON in reduced units; 0 here, so that bodies in
    // SI units turn: the same comparisons.)
    static void kick(const double q[4], const double inertia[3], const Vec3& torque, double dt, double p[4]) {
        const double t_world[3] = {torque.x(), torque.y(), torque.z()};
        double t[3];
        rotate(q, -1.0, t_world, t);
        for (int i = 0; i < 3; ++i)
            if (inertia[i] <= 0.0) t[i] = 0.0;
        double f[4];
        times_vector(q, t, f);
        for (int i = 0; i < 4; ++i) p[i] += dt * f[i];
    }

    static void rotor(int k, double p[4], double q[4], const double inertia[3], double h) {
        if (inertia[k - 1] <= 0.0) return;
        double pk[4], qk[4];
        permute(k, p, pk);
        permute(k, q, qk);
        const double phi = 0.25 / inertia[k - 1] * (p[0] * qk[0] + p[1] * qk[1] + p[2] * qk[2] + p[3] * qk[3]);
        const double c = std::cos(h * phi), s = std::sin(h * phi);
        for (int i = 0; i < 4; ++i) {
            p[i] = c * p[i] + s * pk[i];
            q[i] = c * q[i] + s * qk[i];
        }
    }

    // w = q (L'/I) q* with L' = 1/2 vec(q* p).
    static Vec3 omega(const double q[4], const double p[4], const double inertia[3]) {
        const double s = q[0], v[3] = {q[1], q[2], q[3]}, pv[3] = {p[1], p[2], p[3]};
        const double w_body[3] = {0.5 * (s * pv[0] - p[0] * v[0] - (v[1] * pv[2] - v[2] * pv[1])) / inertia[0],
                                  0.5 * (s * pv[1] - p[0] * v[1] - (v[2] * pv[0] - v[0] * pv[2])) / inertia[1],
                                  0.5 * (s * pv[2] - p[0] * v[2] - (v[0] * pv[1] - v[1] * pv[0])) / inertia[2]};
        double w[3];
        rotate(q, 1.0, w_body, w);
        return {w[0], w[1], w[2]};
    }

    static void start(const RigidBody& b, Memory& m) {
        double q[4], inertia[3];
        unpack(b, q, inertia);
        normalise(q);
        const double w_world[3] = {b.omega.x(), b.omega.y(), b.omega.z()};
        double w[3];
        rotate(q, -1.0, w_world, w);
        const double l[3] = {inertia[0] * w[0], inertia[1] * w[1], inertia[2] * w[2]};
        times_vector(q, l, m.p);
        for (double& x : m.p) x *= 2.0;  // p = 2 q (0, L')
    }

    static void predict(RigidBody& b, Memory& m, double dt) {
        double q[4], inertia[3];
        unpack(b, q, inertia);
        kick(q, inertia, b.torque, dt, m.p);
        rotor(3, m.p, q, inertia, 0.5 * dt);
        rotor(2, m.p, q, inertia, 0.5 * dt);
        rotor(1, m.p, q, inertia, dt);
        rotor(2, m.p, q, inertia, 0.5 * dt);
        rotor(3, m.p, q, inertia, 0.5 * dt);
        normalise(q);  // HOOMD's "renormalize", once per step
        b.q = Quat(q[0], q[1], q[2], q[3]);
        b.omega = omega(q, m.p, inertia);
    }

    static void correct(RigidBody& b, Memory& m, double dt) {
        double q[4], inertia[3];
        unpack(b, q, inertia);
        kick(q, inertia, b.torque, dt, m.p);
        b.omega = omega(q, m.p, inertia);
    }
};

const RegisterScheme<NoSquishHoomd> registration(
    "no_squish__hoomd", "public-code counterpart: NO_SQUISH as in HOOMD-blue's TwoStepNVE",
    "HOOMD-blue hoomd/md/TwoStepNVE.cc integrateStepOne/integrateStepTwo, read and written anew",
    "Torque to the body frame by a quaternion rotation; kick of p with q (0, T'); free rotors 3, 2, 1, 2, 3 over dt/2, "
    "dt/2, dt, dt/2, dt/2 with libm's sin and cos, each skipped for a zero moment; q renormalised; kick. For the cost "
    "table only.",
    public_codes::no_squish_claims());

}  // namespace
}  // namespace rotbench
