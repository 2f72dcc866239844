// Must not build: a rotation policy whose rotate is misspelt.
#include "schemes/kick_drift_kick.hpp"

namespace {
using namespace rotbench;
struct Rotation {
    static Quat rotat(const RigidBody& start, const Vec3&, double) { return start.q; }
};
const RegisterScheme<KickDriftKick<Rotation>> registration("probe", "", "");
}  // namespace
