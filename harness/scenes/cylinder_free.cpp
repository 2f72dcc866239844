// `cylinder_free`: seed 000, test case 1 (Munjiza et al.'s free cylinder). A cylinder of
// radius 0.5 m, height 1.5 m and density 1 (so I'z/I'x = 0.5) spins freely with
// w0 = (0, 1, 100) rad/s in both frames (q0 = identity) for 0.5 s. No force, no torque.
// Exact answer: w'x = sin 50t, w'y = cos 50t, w'z = 100 (the seed's eq. 65b prints sin
// for w'y; cos is what Euler's equations give for this start), and the closed-form
// orientation of FreeRigidBody.
#include "harness/scenes/scene.hpp"
#include "harness/scenes/single_body.hpp"
#include "schemes/detail/free_rigid_body.hpp"

#include <optional>

namespace rotbench {
namespace {

class CylinderFree final : public Scene {
public:
    static constexpr SceneTraits traits{.reference = ReferenceKind::closed_form, .conserves_angular_momentum = true};
    CylinderFree() {
        params.declare("radius", {0.5}, "m", "cylinder radius");
        params.declare("height", {1.5}, "m", "cylinder height (along body z)");
        params.declare("density", {1.0}, "kg/m^3", "density");
        params.declare("omega0", {0.0, 1.0, 100.0}, "rad/s", "initial angular velocity, body frame");
        params.declare("q0", {1.0, 0.0, 0.0, 0.0}, "-", "initial orientation (w, x, y, z), body to world");
        params.declare("t_end", {0.5}, "s", "duration");
    }

    void prepare() override {
        cylinder_ = solid_cylinder(params);
        params.positive("t_end");
        exact_.emplace(cylinder_.inertia, params.quat("q0"), params.vec3("omega0"));
    }

    Bodies initial_state() const override {
        return single_body(cylinder_.mass, cylinder_.inertia, params.quat("q0"), params.vec3("omega0"));
    }
    // A ladder by halving from 1e-3, and Table 1's steps.
    std::vector<double> default_dts() const override { return halving_ladder(1e-3, 8, {1e-2, 1e-4, 1e-5, 1e-6}); }
    std::vector<double> quick_dts() const override { return {1e-2, 1e-3, 1e-4, 1e-5}; }

    void evaluate_forces(Bodies& b, double) const override {
        b.force.set(0, Vec3::Zero());
        b.torque.set(0, Vec3::Zero());
    }
    std::optional<TorqueLaw> torque_law() const override { return TorqueLaw{}; }

    ReferenceState exact(std::size_t, double t) const override {
        return {exact_->orientation(t), exact_->omega_world(t)};
    }

private:
    SolidCylinder cylinder_{};
    std::optional<FreeRigidBody> exact_;
};

const RegisterScene<CylinderFree> registration(
    "cylinder_free", "torque-free cylinder, I'z/I'x = 0.5, w0 = (0, 1, 100) rad/s, 0.5 s (seed test case 1)",
    "Irazabal et al., seed 000, section 3.1.1 and Table 1 (after Munjiza et al.)");

}  // namespace
}  // namespace rotbench
