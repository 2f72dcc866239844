// `particle_contact`: a user's particle as `rotbench advise` describes it, in the contact of
// the contact-pair scenes: two copies of the body (principal moments I, mass M) joined tip
// to tip by a linear spring-dashpot of stiffness k and damping ratio zeta, each spinning at w
// about a generic axis. The contact arm is the longest semi-axis of the ellipsoid with the
// same mass and moments, a^2 = 5 (I2 + I3 - I1) / (2 M) with I1 the least moment: the arm
// that makes A_max, and so the stability limit, the most demanding. Not in the default suite.
#include "harness/scenes/contact_pair.hpp"

#include <algorithm>
#include <numbers>

namespace rotbench {
namespace {

class ParticleContact final : public ContactPairScene {
public:
    static constexpr SceneTraits traits{.reference = ReferenceKind::odeint, .in_default_suite = false};
    ParticleContact() {
        // A ballast-like grain: the ellipsoid of semi-axes 30, 20, 15 mm at 0.1 kg.
        params.declare("inertia", {1.25e-5, 2.25e-5, 2.6e-5}, "kg m^2", "principal moments of the particle");
        params.declare("mass", {0.1}, "kg", "particle mass");
        params.declare("omega", {10.0}, "rad/s", "spin rate of each particle, about a generic axis");
        params.declare("t_end", {0.01}, "s", "duration (rotbench advise: 20 periods of the fastest contact mode)");
        params.set("stiffness", {1e6});
    }
    void prepare() override {
        Vec3 i = params.principal_moments("inertia");
        std::sort(i.data(), i.data() + 3);  // body x: the least moment, the longest semi-axis
        mass_ = params.positive("mass");
        const double a2 = 5.0 * (i.y() + i.z() - i.x()) / (2.0 * mass_);
        params.require(a2 > 0.0, "inertia", "the moments describe no body of positive extent");
        omega_ = params.number("omega");
        params.require(omega_ >= 0.0, "omega", "must not be negative");
        const double a = std::sqrt(a2);
        // A client sees the ellipsoid of these moments, where one exists.
        const double b2 = 5.0 * (i.x() + i.z() - i.y()) / (2.0 * mass_), c2 = 5.0 * (i.x() + i.y() - i.z()) / (2.0 * mass_);
        Shape shape{"moments", {}};
        if (b2 > 0.0 && c2 > 0.0) shape = {"ellipsoid", {a, std::sqrt(b2), std::sqrt(c2)}};
        set_pair(shape, mass_, i, a, Quat(Eigen::AngleAxisd(std::numbers::pi / 2.0, Vec3::UnitX())), 2.0 * a);
    }
    Bodies initial_state() const override {
        Bodies b = ContactPairScene::initial_state();
        b.omega.set(0, b.omega[0] + omega_ * Vec3(1.0, 2.0, 3.0).normalized());
        b.omega.set(1, b.omega[1] + omega_ * Vec3(-3.0, 1.0, 2.0).normalized());
        return b;
    }
    // Ladders from Peng's prediction down, for `rotbench run --scenes particle_contact`.
    std::vector<double> default_dts() const override { return halving_ladder(0.5 * predicted_limit(), 5); }
    std::vector<double> quick_dts() const override { return halving_ladder(0.5 * predicted_limit(), 3); }

private:
    double mass_ = 0, omega_ = 0;
};

const RegisterScene<ParticleContact> registration(
    "particle_contact",
    "a user's particle (moments, mass, spin) in the contact-pair scenes' linear spring-dashpot contact; for rotbench advise",
    "Peng, Burns & Hanley, seed 004, eq. 29 (contact) and eq. 46 (its critical step)");

}  // namespace
}  // namespace rotbench
