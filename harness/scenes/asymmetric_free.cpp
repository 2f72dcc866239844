// `asymmetric_free`: the torque-free asymmetric top of Hairer, Lubich & Wanner
// (Geometric Numerical Integration, sec. I.5): I' = (2, 1, 2/3), body angular momentum
// (cos 1.1, 0, sin 1.1), q0 = identity. Exact answer: FreeRigidBody (elliptic functions).
// These moments violate the triangle inequality (no real body has them); the scene keeps
// them because they are the published test, and accepts any positive moments.
#include "harness/scenes/free_top.hpp"

#include <cmath>

namespace rotbench {
namespace {

class AsymmetricFree final : public FreeTopScene {
public:
    AsymmetricFree() {
        params.declare("inertia", {2.0, 1.0, 2.0 / 3.0}, "kg m^2",
                       "principal moments I'1, I'2, I'3 (any positive values: HLW's default is no real body)");
        params.declare("momentum0", {std::cos(1.1), 0.0, std::sin(1.1)}, "kg m^2/s", "initial angular momentum, body frame");
        params.declare("q0", {1.0, 0.0, 0.0, 0.0}, "-", "initial orientation (w, x, y, z), body to world");
        params.declare("t_end", {20.0}, "s", "duration (about two periods of the body motion)");
    }
    void prepare() override {
        // HLW's moments violate the triangle inequality (2 > 1 + 2/3): a test of Euler's
        // equations, not a body that exists. This scene keeps them: they are the published test.
        const Vec3 inertia = params.principal_moments("inertia", /*real_body=*/false);
        set_motion(inertia, params.quat("q0"), params.vec3("momentum0").cwiseQuotient(inertia));
    }
    std::vector<double> default_dts() const override { return halving_ladder(1e-1, 8); }
    std::vector<double> quick_dts() const override { return halving_ladder(1e-1, 4); }
};

const RegisterScene<AsymmetricFree> registration(
    "asymmetric_free", "torque-free asymmetric top, I' = (2, 1, 2/3), L' = (cos 1.1, 0, sin 1.1), 20 s",
    "Hairer, Lubich & Wanner, Geometric Numerical Integration, sec. I.5; closed form: Landau & Lifshitz sec. 37");

}  // namespace
}  // namespace rotbench
