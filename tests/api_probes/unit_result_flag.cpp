// Must not build: the old flag, which a misspelling would have turned into another path.
#include "schemes/kick_drift_kick.hpp"

namespace {
using namespace rotbench;
struct Rotation {
    static constexpr bool unit_result = true;
    static Quat rotate(const RigidBody& start, const Vec3&, double) { return start.q; }
};
const RegisterScheme<KickDriftKick<Rotation>> registration("probe", "", "");
}  // namespace
