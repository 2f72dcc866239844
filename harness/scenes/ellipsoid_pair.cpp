// `ellipsoid_pair`: two ellipsoids with semi-axes 3, 2, 1 m (density 1000 kg/m^3) in the
// orthogonal tip-to-tip contact of seed 004, Fig. 2: long axes along the contact normal,
// the second turned 90 degrees about it; linear spring-dashpot, k = 1e10 N/m.
#include "harness/scenes/contact_pair.hpp"

#include <numbers>

namespace rotbench {
namespace {

class EllipsoidPair final : public ContactPairScene {
public:
    EllipsoidPair() {
        params.declare("semi_axes", {3.0, 2.0, 1.0}, "m", "semi-axes a >= b >= c (along body x, y, z)");
        params.declare("density", {1000.0}, "kg/m^3", "density");
        params.declare("t_end", {0.5}, "s", "duration (about 200 periods of the fastest contact mode)");
    }
    void prepare() override {
        const Vec3 s = params.positive_vec3("semi_axes");
        params.require(s.x() >= s.y() && s.y() >= s.z(), "semi_axes", "must be ordered a >= b >= c");
        const double m = params.positive("density") * 4.0 / 3.0 * std::numbers::pi * s.prod();
        const Vec3 inertia = m / 5.0 * Vec3(s.y() * s.y() + s.z() * s.z(), s.x() * s.x() + s.z() * s.z(),
                                            s.x() * s.x() + s.y() * s.y());
        set_pair({"ellipsoid", {s.x(), s.y(), s.z()}}, m, inertia, s.x(), Quat(Eigen::AngleAxisd(std::numbers::pi / 2.0, Vec3::UnitX())), 2.0 * s.x());
    }
    std::vector<double> default_dts() const override { return halving_ladder(4e-4, 5); }
    std::vector<double> quick_dts() const override { return halving_ladder(4e-4, 3); }
};

const RegisterScene<EllipsoidPair> registration(
    "ellipsoid_pair", "two ellipsoids (3, 2, 1 m, 1000 kg/m^3), orthogonal tip-to-tip linear contact, k = 1e10 N/m",
    "Peng, Burns & Hanley, seed 004, Fig. 2 and sec. 6");

}  // namespace
}  // namespace rotbench
