// Must not build: a claim's field misspelt in the registration.
#include "schemes/kick_drift_kick.hpp"

namespace {
using namespace rotbench;
struct Rotation {
    static Quat rotate(const RigidBody& start, const Vec3&, double) { return start.q; }
};
const RegisterScheme<KickDriftKick<Rotation>> registration("probe", "", "", "", {.famly = "seed"});
}  // namespace
