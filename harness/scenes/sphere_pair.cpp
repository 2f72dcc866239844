// `sphere_pair`: two identical spheres (radius 0.5 m, density 1000 kg/m^3) in one linear
// spring-dashpot contact (k = 1e10 N/m), for the stability study. Seed 004 sec. 4.3: here
// A_max = 7/m and the undamped critical step of eq. 49 is (2/sqrt 7) sqrt(m/k).
#include "harness/scenes/contact_pair.hpp"

#include <numbers>

namespace rotbench {
namespace {

class SpherePair final : public ContactPairScene {
public:
    SpherePair() {
        params.declare("radius", {0.5}, "m", "sphere radius");
        params.declare("density", {1000.0}, "kg/m^3", "density");
        params.declare("t_end", {0.1}, "s", "duration (about 200 periods of the fastest contact mode)");
    }
    void prepare() override {
        const double r = params.positive("radius");
        const double m = params.positive("density") * 4.0 / 3.0 * std::numbers::pi * r * r * r;
        set_pair({"sphere", {r}}, m, Vec3::Constant(0.4 * m * r * r), r, Quat::Identity(), 2.0 * r);
    }
    std::vector<double> default_dts() const override { return halving_ladder(1e-4, 5); }
    std::vector<double> quick_dts() const override { return halving_ladder(1e-4, 3); }
};

const RegisterScene<SpherePair> registration(
    "sphere_pair", "two spheres (r = 0.5 m, 1000 kg/m^3) in a linear spring-dashpot contact, k = 1e10 N/m",
    "Peng, Burns & Hanley, seed 004, sec. 4.3");

}  // namespace
}  // namespace rotbench
