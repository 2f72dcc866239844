// `tumbling_brick`: a torque-free solid brick of ballast-like size and density (60 x 40 x 20 mm,
// 2700 kg/m^3, principal moments in the ratio 1 : 2 : 2.6), spinning at about 10 rad/s mostly
// about its major axis with a wobble: a real, clearly asymmetric body, far from the separatrix
// and from a principal axis, so that no scheme's error cancels by symmetry. Two seconds are
// about five periods of the body motion. Exact answer: the closed form (FreeRigidBody).
#include "harness/scenes/free_top.hpp"

namespace rotbench {
namespace {

class TumblingBrick final : public FreeTopScene {
public:
    TumblingBrick() {
        params.declare("size", {0.06, 0.04, 0.02}, "m", "edge lengths along body x, y, z");
        params.declare("density", {2700.0}, "kg/m^3", "density");
        params.declare("omega0", {2.0, 3.0, 10.0}, "rad/s", "initial angular velocity, body frame");
        params.declare("q0", {1.0, 0.0, 0.0, 0.0}, "-", "initial orientation (w, x, y, z), body to world");
        params.declare("t_end", {2.0}, "s", "duration (about five periods of the body motion)");
    }
    void prepare() override {
        const Vec3 size = params.positive_vec3("size");
        const double mass = params.positive("density") * size.prod();
        const Vec3 s2 = size.cwiseAbs2();
        const Vec3 inertia = mass / 12.0 * Vec3(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y());
        set_motion(inertia, params.quat("q0"), params.vec3("omega0"));
        mass_ = mass;
    }
    Bodies initial_state() const override {
        Bodies b = FreeTopScene::initial_state();
        b.mass[0] = mass_;
        return b;
    }
    std::vector<double> default_dts() const override { return halving_ladder(1e-2, 6); }
    std::vector<double> quick_dts() const override { return halving_ladder(1e-2, 3); }

private:
    double mass_ = 1.0;
};

const RegisterScene<TumblingBrick> registration(
    "tumbling_brick", "torque-free brick, 60 x 40 x 20 mm, 2700 kg/m^3, w0 = (2, 3, 10) rad/s, 2 s",
    "a solid brick, I1 = m (b^2 + c^2) / 12 and so on; closed form: Landau & Lifshitz sec. 37");

}  // namespace
}  // namespace rotbench
