// A transcription of the built-in `direct` scheme (schemes/direct.cpp, seed 000 eqs. 33-43),
// built out of tree as a plug-in: it must give direct's bits (same_bits.py). It is a test
// fixture, deliberately a copy; the kernel is not shared with the built-in on purpose.
#include "schemes/quaternion.hpp"
#include "schemes/scheme.hpp"

namespace {

using namespace rotbench;

template <class S = double>
struct DirectCopy {
    template <class T>
    using rebind = DirectCopy<T>;
    struct Memory {
        QuatT<S> q_start;
    };
    static void start(const RigidBodyT<S>&, Memory&) {}
    static void predict(RigidBodyT<S>& b, Memory& m, double dt) {
        m.q_start = b.q;
        const Vec3T<S> torque_body = to_body(b.q, b.torque);
        const Vec3T<S> alpha_body = euler_acceleration(to_body(b.q, b.omega), torque_body, b.inertia);
        b.omega += 0.5 * dt * to_world(b.q, alpha_body);
        b.q = rotation_increment<S>(b.omega, dt) * b.q;
    }
    static void correct(RigidBodyT<S>& b, Memory& m, double dt) {
        const QuatT<S>& frame = m.q_start;
        const Vec3T<S> alpha_body = euler_acceleration(to_body(frame, b.omega), to_body(frame, b.torque), b.inertia);
        b.omega += 0.5 * dt * to_world(frame, alpha_body);
    }
};

const RegisterScheme<DirectCopy<>> registration("direct_copy", "test plug-in: a transcription of direct", "tests/installed_plugin",
                                                "", {.without_torque = {1, "as direct"}, .with_torque = {1, "as direct"}});

}  // namespace
