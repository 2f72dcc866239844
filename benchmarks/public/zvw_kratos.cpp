// `zvw__kratos`: Zhao & van Wachem's quaternion step as Kratos DEMApplication's
// QuaternionIntegrationScheme steps a rigid body (CalculateNewRotationalVariablesOfRigidBodyElements,
// its predict and correct flags), written anew for the cost table's side-by-side comparison
// with rotbench's `zvw`. Kratos keeps the body-frame w' from step to step, takes the half-step
// orientation in predict, and in correct the torque in the frame of that half-step orientation,
// then q^{n+1} and w from w'. Another reading than `zvw`: it claims nothing; only its cost is
// compared.
#include "benchmarks/public/kratos_math.hpp"

namespace rotbench {
namespace {

using namespace kratos_style;

struct ZvwKratos {
    struct Memory {
        double omega_body[3];       // LOCAL_ANGULAR_VELOCITY
        double omega_body_half[3];  // LOCAL_AUX_ANGULAR_VELOCITY
        Quaternion4 q_half;         // AUX_ORIENTATION
    };

    static void start(const RigidBody& b, Memory& m) {
        const double w[3] = {b.omega.x(), b.omega.y(), b.omega.z()};
        to_local(of(b.q), w, m.omega_body);
    }

    static void predict(RigidBody& b, Memory& m, double dt) {
        const Quaternion4 q = of(b.q);
        const double inertia[3] = {b.inertia.x(), b.inertia.y(), b.inertia.z()}, torque[3] = {b.torque.x(), b.torque.y(), b.torque.z()};
        double torque_body[3], alpha[3], quarter_body[3], quarter[3], rotation[3];
        to_local(q, torque, torque_body);
        euler_acceleration(m.omega_body, inertia, torque_body, alpha);
        for (int j = 0; j < 3; ++j) {
            quarter_body[j] = m.omega_body[j] + 0.25 * alpha[j] * dt;
            m.omega_body_half[j] = m.omega_body[j] + 0.5 * alpha[j] * dt;
        }
        rotate(q, quarter_body, quarter);
        for (int j = 0; j < 3; ++j) rotation[j] = 0.5 * quarter[j] * dt;
        m.q_half = turned(q, rotation);
    }

    static void correct(RigidBody& b, Memory& m, double dt) {
        const double inertia[3] = {b.inertia.x(), b.inertia.y(), b.inertia.z()}, torque[3] = {b.torque.x(), b.torque.y(), b.torque.z()};
        double torque_body[3], alpha[3], w[3], rotation[3];
        to_local(m.q_half, torque, torque_body);
        euler_acceleration(m.omega_body_half, inertia, torque_body, alpha);
        for (int j = 0; j < 3; ++j) m.omega_body[j] += alpha[j] * dt;
        rotate(m.q_half, m.omega_body, w);
        for (int j = 0; j < 3; ++j) rotation[j] = w[j] * dt;
        const Quaternion4 q = turned(of(b.q), rotation);
        rotate(q, m.omega_body, w);
        b.q = to_quat(q);
        b.omega = Vec3(w[0], w[1], w[2]);
    }
};

const RegisterScheme<ZvwKratos> registration(
    "zvw__kratos", "public-code counterpart: Zhao-van Wachem step as in Kratos DEMApplication",
    "Kratos applications/DEMApplication/custom_strategies/schemes/quaternion_integration_scheme.cpp, read and written anew",
    "w' kept; predict: torque at q^n, quarter and half w', q_half; correct: torque at q_half, w' += dt alpha, "
    "q^{n+1} from w at q_half, w from w' at q^{n+1}. For the cost table only: it claims nothing.");

}  // namespace
}  // namespace rotbench
