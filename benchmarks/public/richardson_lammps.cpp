// `richardson__lammps`: the Richardson quaternion update as LAMMPS's fix rigid steps it
// (MathExtra::richardson, angmom_to_omega through the stored body axes), written anew for
// the cost table's side-by-side comparison with rotbench's `richardson`. The same map in
// exact arithmetic; the counterpart is named by the id, `<scheme>__<code>`.
#include "benchmarks/public/lammps_math.hpp"

namespace rotbench {
namespace {

using namespace lammps_style;

struct RichardsonLammps {
    struct Memory {
        double angmom[3];  // world
        Axes axes;         // of q^n, kept from the end of the previous step, as fix rigid does
    };

    static void start(const RigidBody& b, Memory& m) {
        double q[4], inertia[3];
        unpack(b, q, inertia);
        normalise(q);
        m.axes = axes_of(q);
        const double w[3] = {b.omega.x(), b.omega.y(), b.omega.z()};
        momentum_from_omega(w, m.axes, inertia, m.angmom);
    }

    static void predict(RigidBody& b, Memory& m, double dt) {
        double q[4], inertia[3], w[3], wq[4], full[4], half[4];
        unpack(b, q, inertia);
        for (int i = 0; i < 3; ++i) m.angmom[i] += 0.5 * dt * b.torque[i];
        omega_from_momentum(m.angmom, m.axes, inertia, w);
        const double dtq = 0.5 * dt;
        vector_times_quaternion(w, q, wq);
        for (int i = 0; i < 4; ++i) full[i] = q[i] + dtq * wq[i];
        normalise(full);
        for (int i = 0; i < 4; ++i) half[i] = q[i] + 0.5 * dtq * wq[i];
        normalise(half);
        omega_from_momentum(m.angmom, axes_of(half), inertia, w);  // mq_to_omega at the half step
        vector_times_quaternion(w, half, wq);
        for (int i = 0; i < 4; ++i) half[i] += 0.5 * dtq * wq[i];
        normalise(half);
        for (int i = 0; i < 4; ++i) q[i] = 2.0 * half[i] - full[i];
        normalise(q);
        m.axes = axes_of(q);
        omega_from_momentum(m.angmom, m.axes, inertia, w);
        b.q = Quat(q[0], q[1], q[2], q[3]);
        b.omega = Vec3(w[0], w[1], w[2]);
    }

    static void correct(RigidBody& b, Memory& m, double dt) {
        const double inertia[3] = {b.inertia.x(), b.inertia.y(), b.inertia.z()};  // q is not needed here
        double w[3];
        for (int i = 0; i < 3; ++i) m.angmom[i] += 0.5 * dt * b.torque[i];
        omega_from_momentum(m.angmom, m.axes, inertia, w);
        b.omega = Vec3(w[0], w[1], w[2]);
    }
};

const RegisterScheme<RichardsonLammps> registration(
    "richardson__lammps", "public-code counterpart: Richardson update as in LAMMPS fix rigid",
    "LAMMPS src/math_extra.cpp MathExtra::richardson and src/RIGID/fix_rigid.cpp, read and written anew",
    "Kick of L; w from L through the body axes of q^n; q by 2 q(two half Euler steps) - q(one Euler step), w at the "
    "half step from the axes of the normalised half-step q; axes of q^{n+1}; kick. For the cost table only.",
    {.without_torque = {2, "the same map as richardson"},
     .with_torque = {2, "the same map as richardson"},
     .conserves_momentum = true});

}  // namespace
}  // namespace rotbench
