// `no_squish__lammps`: NO_SQUISH as LAMMPS's fix rigid/nve steps it (MathExtra::
// no_squish_rotate on the conjugate quaternion momentum p = 2 S(q) (0, L'), with libm's sin
// and cos, torque kicks on p), written anew for the cost table's side-by-side comparison
// with rotbench's `no_squish`. The same map in exact arithmetic.
#include "benchmarks/public/lammps_math.hpp"
#include "benchmarks/public/no_squish_common.hpp"

namespace rotbench {
namespace {

using namespace lammps_style;
using public_codes::permute;

struct NoSquishLammps {
    struct Memory {
        double p[4];  // conjugate quaternion momentum
    };

    static void free_rotor(int k, double p[4], double q[4], const double inertia[3], double h) {
        double kp[4], kq[4];
        permute(k, p, kp);
        permute(k, q, kq);
        const double phi = (p[0] * kq[0] + p[1] * kq[1] + p[2] * kq[2] + p[3] * kq[3]) / (4.0 * inertia[k - 1]);
        const double c = std::cos(h * phi), s = std::sin(h * phi);
        for (int i = 0; i < 4; ++i) {
            p[i] = c * p[i] + s * kp[i];
            q[i] = c * q[i] + s * kq[i];
        }
    }

    // w from p: L' = 1/2 vec(q* p), then through the axes of q.
    static Vec3 omega(const double q[4], const double p[4], const double inertia[3]) {
        double lb[3];
        conjugate_times_quaternion_vector(q, p, lb);
        const Axes a = axes_of(q);
        double w[3];
        for (int i = 0; i < 3; ++i) w[i] = 0.5 * lb[0] / inertia[0] * a.ex[i] + 0.5 * lb[1] / inertia[1] * a.ey[i] +
                                           0.5 * lb[2] / inertia[2] * a.ez[i];
        return {w[0], w[1], w[2]};
    }

    // p += dt q (0, T'): the kick of L' by dt/2 T', written on p.
    static void kick(const double q[4], const Vec3& torque, double dt, double p[4]) {
        const Axes a = axes_of(q);
        const double t[3] = {torque.x(), torque.y(), torque.z()};
        const double tb[3] = {dot3(t, a.ex), dot3(t, a.ey), dot3(t, a.ez)};
        double f[4];
        quaternion_times_vector(q, tb, f);
        for (int i = 0; i < 4; ++i) p[i] += dt * f[i];
    }

    static void start(const RigidBody& b, Memory& m) {
        double q[4], inertia[3];
        unpack(b, q, inertia);
        normalise(q);
        const Axes a = axes_of(q);
        const double w[3] = {b.omega.x(), b.omega.y(), b.omega.z()};
        const double lb[3] = {dot3(w, a.ex) * inertia[0], dot3(w, a.ey) * inertia[1], dot3(w, a.ez) * inertia[2]};
        quaternion_times_vector(q, lb, m.p);
        for (double& x : m.p) x *= 2.0;
    }

    static void predict(RigidBody& b, Memory& m, double dt) {
        double q[4], inertia[3];
        unpack(b, q, inertia);
        kick(q, b.torque, dt, m.p);
        const double dtq = 0.5 * dt;
        free_rotor(3, m.p, q, inertia, dtq);
        free_rotor(2, m.p, q, inertia, dtq);
        free_rotor(1, m.p, q, inertia, dt);
        free_rotor(2, m.p, q, inertia, dtq);
        free_rotor(3, m.p, q, inertia, dtq);
        b.q = Quat(q[0], q[1], q[2], q[3]);
        b.omega = omega(q, m.p, inertia);
    }

    static void correct(RigidBody& b, Memory& m, double dt) {
        double q[4], inertia[3];
        unpack(b, q, inertia);
        kick(q, b.torque, dt, m.p);
        b.omega = omega(q, m.p, inertia);
    }
};

const RegisterScheme<NoSquishLammps> registration(
    "no_squish__lammps", "public-code counterpart: NO_SQUISH as in LAMMPS fix rigid/nve",
    "LAMMPS src/math_extra.cpp MathExtra::no_squish_rotate and src/RIGID/fix_rigid_nve.cpp, read and written anew",
    "Kick of the quaternion momentum p with q (0, T'); free rotors 3, 2, 1, 2, 3 over dt/2, dt/2, dt, dt/2, dt/2 "
    "with libm's sin and cos; kick. For the cost table only.",
    public_codes::no_squish_claims());

}  // namespace
}  // namespace rotbench
