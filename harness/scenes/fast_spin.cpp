// `fast_spin`: a torque-free asymmetric body, I' = (1, 2, 3) kg m^2 (B_max = 1, seed 004
// eq. 54), spinning at omega_max about its major axis (stable: no physical flips) with a
// 1 % wobble, for the rotation-dominant critical step of seed 004 eq. 57, 1/(w_max B_max).
#include "harness/scenes/free_top.hpp"
#include "harness/scenes/stability_probe.hpp"
#include "references/critical_time_step.hpp"

#include <numbers>

namespace rotbench {
namespace {

class FastSpin final : public FreeTopScene, public StabilityProbe {
public:
    FastSpin() {
        params.declare("inertia", {1.0, 2.0, 3.0}, "kg m^2", "principal moments I'1, I'2, I'3");
        params.declare("omega_max", {100.0}, "rad/s", "spin rate about the major axis");
        params.declare("t_end", {1.0}, "s", "duration");
    }
    void prepare() override {
        inertia_ = params.principal_moments("inertia");
        omega_max_ = params.positive("omega_max");
        set_motion(inertia_, Quat::Identity(), Vec3(0.01, 0.01, 1.0) * omega_max_);
    }
    std::vector<double> default_dts() const override { return halving_ladder(1e-3, 5); }
    std::vector<double> quick_dts() const override { return halving_ladder(1e-3, 3); }

    double predicted_limit() const override { return peng::rotation_dominant(omega_max_, peng::b_max(inertia_)); }
    double period() const override { return 2.0 * std::numbers::pi / omega_max_; }
    bool linearisable_at_rest() const override { return false; }  // a spin is not a rest state

private:
    Vec3 inertia_;
    double omega_max_ = 0;
};

const RegisterScene<FastSpin> registration(
    "fast_spin", "torque-free body, I' = (1, 2, 3), spinning at omega_max = 100 rad/s about its major axis",
    "Peng, Burns & Hanley, seed 004, sec. 5 (rotation-dominant critical time step, eq. 57)");

}  // namespace
}  // namespace rotbench
