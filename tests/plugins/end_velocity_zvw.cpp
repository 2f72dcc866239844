// Test plug-in: a reading of Zhao & van Wachem's scheme found in a widely used DEM code. It
// registers zvw's claims (second order without torque), but rotates q with the end-of-step
// body angular velocity, in the body frame of q^n, and takes the torque into the half-step
// frame: first order in q and in the world angular velocity. Its body-frame w' follows the
// same mid-point rule as zvw's, so seed Table 1 (body-frame RMS) cannot tell them apart.
// The default gate must fail it on its order claim.
#include "schemes/quaternion.hpp"
#include "schemes/scheme.hpp"

namespace {

using namespace rotbench;

struct EndVelocityZvw {
    struct Memory {
        Vec3 omega_body;       // w'^n
        Vec3 omega_body_half;  // w'^{n+1/2}
        Quat q_half;
    };
    static void start(const RigidBody&, Memory&) {}
    static void predict(RigidBody& b, Memory& m, double dt) {
        m.omega_body = to_body(b.q, b.omega);
        const Vec3 torque_body = to_body(b.q, b.torque);
        m.omega_body_half = m.omega_body + 0.5 * dt * euler_acceleration(m.omega_body, torque_body, b.inertia);
        const Vec3 omega_body_end = m.omega_body + dt * euler_acceleration(m.omega_body_half, torque_body, b.inertia);
        m.q_half = b.q * rotation_increment(omega_body_end, 0.5 * dt);
        b.q = b.q * rotation_increment(omega_body_end, dt);  // the end-of-step velocity, body frame of q^n
        b.omega = to_world(b.q, omega_body_end);
    }
    static void correct(RigidBody& b, Memory& m, double dt) {
        const Vec3 torque_body = to_body(m.q_half, b.torque);  // the torque in the half-step frame
        b.omega = to_world(b.q, m.omega_body + dt * euler_acceleration(m.omega_body_half, torque_body, b.inertia));
    }
};

const RegisterScheme<EndVelocityZvw> registration(
    "zvw_end_velocity", "test plug-in: ZvW rotating with the end-of-step body velocity (claims zvw's orders)", "tests/plugins",
    "", {.without_torque = {2, "as zvw (claimed, not delivered)"}, .with_torque = {1, "as zvw"}});

}  // namespace
