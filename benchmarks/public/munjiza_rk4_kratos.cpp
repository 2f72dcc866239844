// `munjiza_rk4__kratos`: the Runge-Kutta average of the angular velocity as Kratos
// DEMApplication's RungeKuttaScheme steps a rigid body (CalculateNewRotationalVariablesOfRigidBodyElements),
// written anew for the cost table's side-by-side comparison with rotbench's `munjiza_rk4`: the
// same map as the seed's eqs. 44-53 with the authors' small-angle series, each w = I(q)^-1 H
// through a world inverse tensor built by six rotations. Its small-angle branch differs from
// `munjiza_rk4` where |w| dt/4 < 2.7e-4 (docs/findings.md): it claims nothing; only its cost is
// compared.
#include "benchmarks/public/kratos_math.hpp"

namespace rotbench {
namespace {

using namespace kratos_style;

struct MunjizaRk4Kratos {
    struct Memory {
        double angmom[3];      // ANGULAR_MOMENTUM, world
        double omega_body[3];  // LOCAL_ANGULAR_VELOCITY, which Kratos stores at every step
    };

    // I(q_turned)^-1 H with q_turned = exp(w h / 2) q (QuaternionCalculateMidAngularVelocities).
    static void omega_at(const Quaternion4& q, const double inertia[3], const double h_world[3], double h, const double w[3],
                         double out[3]) {
        const double rotation[3] = {w[0] * h, w[1] * h, w[2] * h};
        double tensor[3][3];
        world_inverse_tensor(turned(q, rotation), inertia, tensor);
        times(tensor, h_world, out);
    }

    static void start(const RigidBody& b, Memory& m) {
        const Vec3 l = b.q * b.inertia.cwiseProduct(b.q.conjugate() * b.omega);
        m.angmom[0] = l.x(), m.angmom[1] = l.y(), m.angmom[2] = l.z();
    }

    static void predict(RigidBody& b, Memory& m, double dt) {
        const Quaternion4 q = of(b.q);
        const double inertia[3] = {b.inertia.x(), b.inertia.y(), b.inertia.z()};
        for (int j = 0; j < 3; ++j) m.angmom[j] += b.torque[j] * dt;
        const double w1[3] = {b.omega.x(), b.omega.y(), b.omega.z()};
        double w2[3], w3[3], w4[3], rotation[3], w[3], tensor[3][3];
        omega_at(q, inertia, m.angmom, 0.5 * dt, w1, w2);
        omega_at(q, inertia, m.angmom, 0.5 * dt, w2, w3);
        omega_at(q, inertia, m.angmom, dt, w3, w4);
        for (int j = 0; j < 3; ++j) rotation[j] = 0.16666666666666667 * (w1[j] + 2 * w2[j] + 2 * w3[j] + w4[j]) * dt;
        const Quaternion4 next = turned(q, rotation);
        world_inverse_tensor(next, inertia, tensor);
        times(tensor, m.angmom, w);
        to_local(next, w, m.omega_body);
        b.q = to_quat(next);
        b.omega = Vec3(w[0], w[1], w[2]);
    }

    static void correct(RigidBody&, Memory&, double) {}
};

const RegisterScheme<MunjizaRk4Kratos> registration(
    "munjiza_rk4__kratos", "public-code counterpart: Runge-Kutta average of w as in Kratos DEMApplication",
    "Kratos applications/DEMApplication/custom_strategies/schemes/runge_kutta_scheme.cpp, read and written anew",
    "H += dt T; w2, w3, w4 from H at q turned by w1, w2 (dt/2) and w3 (dt), each through a world inverse tensor of six "
    "rotations; q turned by the RK mean; w from H; w' stored. For the cost table only: it claims nothing.");

}  // namespace
}  // namespace rotbench
