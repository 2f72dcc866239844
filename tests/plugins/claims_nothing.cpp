// Test plug-in: a sound second-order scheme (kick, explicit mid-point rotation with exponential
// maps, kick) that registers no claims. The gate holds it to the generic sanity checks only,
// and says so in a warning.
#include "schemes/kick_drift_kick.hpp"

namespace {

using namespace rotbench;

struct MidpointRotation {
    static Quat rotate(const RigidBody& start, const Vec3& momentum, double dt) {
        const Quat q_mid = rotation_increment(start.omega, 0.5 * dt) * start.q;
        return rotation_increment(omega_from_momentum(q_mid, start.inertia, momentum), dt) * start.q;
    }
};

const RegisterScheme<KickDriftKick<MidpointRotation>> registration("claims_nothing",
                                                                   "test plug-in: a sound scheme that registers no claims",
                                                                   "tests/plugins");

}  // namespace
