// Test plug-ins for the cost judge: `plugin_direct`, a copy of direct's kernel (seed 000, eqs.
// 33-43), whose cost is direct's; and `plugin_direct_slowed`, the same kernel that makes every
// step twice, once on a copy it throws away: a scheme made about 2x dearer on purpose.
#include "schemes/quaternion.hpp"
#include "schemes/scheme.hpp"

namespace {

using namespace rotbench;

// Keeps the compiler from dropping the work done on a copy that is never read.
void keep(const RigidBody& b) { asm volatile("" : : "r"(&b) : "memory"); }

template <int Times>
struct DirectTimes {
    struct Memory {
        Quat q_start;
    };
    static void start(const RigidBody&, Memory&) {}
    static void predict(RigidBody& body, Memory& m, double dt) {
        for (int i = Times; i > 0; --i) {
            RigidBody copy = body;
            RigidBody& b = i == 1 ? body : copy;
            m.q_start = b.q;
            const Vec3 alpha_body = euler_acceleration(to_body(b.q, b.omega), to_body(b.q, b.torque), b.inertia);
            b.omega += 0.5 * dt * to_world(b.q, alpha_body);
            b.q = rotation_increment(b.omega, dt) * b.q;
            keep(b);
        }
    }
    static void correct(RigidBody& body, Memory& m, double dt) {
        for (int i = Times; i > 0; --i) {
            RigidBody copy = body;
            RigidBody& b = i == 1 ? body : copy;
            const Vec3 alpha_body = euler_acceleration(to_body(m.q_start, b.omega), to_body(m.q_start, b.torque), b.inertia);
            b.omega += 0.5 * dt * to_world(m.q_start, alpha_body);
            keep(b);
        }
    }
};

const RegisterScheme<DirectTimes<1>> copy("plugin_direct", "test plug-in: a copy of direct", "tests/plugins", "",
                                          {.without_torque = {1, "as direct"}, .with_torque = {1, "as direct"}});
const RegisterScheme<DirectTimes<2>> slowed("plugin_direct_slowed", "test plug-in: direct, every step made twice",
                                            "tests/plugins", "", {.without_torque = {1, "as direct"}, .with_torque = {1, "as direct"}});

}  // namespace
