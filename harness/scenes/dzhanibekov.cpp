// `dzhanibekov`: spin close to the intermediate axis, I' = (1, 2, 3), w0 = (0.01, 2, 0.01)
// rad/s: the body flips over every ~5 s (the tennis-racket or Dzhanibekov effect). The
// flips are physical, the exact solution (FreeRigidBody) has them too, and no blow-up
// rule may call them numerical: the energy of the true motion stays constant.
#include "harness/scenes/free_top.hpp"

namespace rotbench {
namespace {

class Dzhanibekov final : public FreeTopScene {
public:
    Dzhanibekov() {
        params.declare("inertia", {1.0, 2.0, 3.0}, "kg m^2", "principal moments I'1, I'2, I'3");
        params.declare("omega0", {0.01, 2.0, 0.01}, "rad/s", "initial angular velocity, body frame");
        params.declare("q0", {1.0, 0.0, 0.0, 0.0}, "-", "initial orientation (w, x, y, z), body to world");
        params.declare("t_end", {20.0}, "s", "duration (about four flips)");
    }
    void prepare() override {
        set_motion(params.principal_moments("inertia"), params.quat("q0"), params.vec3("omega0"));
    }
    std::vector<double> default_dts() const override { return halving_ladder(1e-1, 8); }
    std::vector<double> quick_dts() const override { return halving_ladder(1e-1, 4); }
};

const RegisterScene<Dzhanibekov> registration(
    "dzhanibekov", "spin near the intermediate axis, I' = (1, 2, 3), w0 = (0.01, 2, 0.01) rad/s: flips, 20 s",
    "closed form: Landau & Lifshitz sec. 37 (near the separatrix)");

}  // namespace
}  // namespace rotbench
