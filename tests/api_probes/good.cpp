// Builds: a rotation policy with a unit result and a kernel-less registration with a family.
#include "schemes/kick_drift_kick.hpp"

namespace {
using namespace rotbench;
struct Rotation : UnitResult {
    static Quat rotate(const RigidBody& start, const Vec3& momentum, double dt) {
        return (rotation_increment(omega_from_momentum(start.q, start.inertia, momentum), dt) * start.q).normalized();
    }
};
const RegisterScheme<KickDriftKick<Rotation>> registration("probe_good", "", "", "", {.family = "seed"});
}  // namespace
