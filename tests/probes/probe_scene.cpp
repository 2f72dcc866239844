// The probe scene of a ROTBENCH_PROBES build: a scene added in one file, with an id that sorts
// before every other (see tests/probes/probe_scheme.cpp). A torque-free asymmetric body,
// I' = (1, 1.5, 2.5) kg m^2, w0 = (1, 0.5, 2) rad/s, with the closed-form reference.
#include "harness/scenes/free_top.hpp"

namespace rotbench {
namespace {

class ProbeTop final : public FreeTopScene {
public:
    ProbeTop() {
        params.declare("inertia", {1.0, 1.5, 2.5}, "kg m^2", "principal moments I'1, I'2, I'3");
        params.declare("omega0", {1.0, 0.5, 2.0}, "rad/s", "initial angular velocity, body frame");
        params.declare("q0", {1.0, 0.0, 0.0, 0.0}, "-", "initial orientation (w, x, y, z), body to world");
        params.declare("t_end", {5.0}, "s", "duration");
    }
    void prepare() override { set_motion(params.principal_moments("inertia"), params.quat("q0"), params.vec3("omega0")); }
    std::vector<double> default_dts() const override { return halving_ladder(2e-2, 6); }
    std::vector<double> quick_dts() const override { return halving_ladder(2e-2, 3); }
};

const RegisterScene<ProbeTop> registration("aaa_probe_top",
                                           "probe: torque-free asymmetric body, closed form (ROTBENCH_PROBES builds only)",
                                           "probe (tests/probes/probe_scene.cpp)");

}  // namespace
}  // namespace rotbench
