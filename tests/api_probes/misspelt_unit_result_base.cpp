// Must not build: the unit-result base misspelt.
#include "schemes/kick_drift_kick.hpp"

namespace {
using namespace rotbench;
struct Rotation : UnitResults {
    static Quat rotate(const RigidBody& start, const Vec3&, double) { return start.q; }
};
const RegisterScheme<KickDriftKick<Rotation>> registration("probe", "", "");
}  // namespace
