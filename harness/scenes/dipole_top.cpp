// `dipole_top`: an asymmetric body carrying a body-fixed magnetic dipole mu in a uniform
// field B: torque T = mu_world x B, which depends on the orientation, so it exercises a
// scheme's torque re-estimate. Energy 1/2 w'.I'w' - mu_world.B is conserved, and so is
// the component of the angular momentum along B. Reference: Odeint.
#include "harness/scenes/scene.hpp"
#include "harness/scenes/single_body.hpp"
#include "schemes/quaternion.hpp"

#include <cmath>

namespace rotbench {
namespace {

class DipoleTop final : public Scene {
public:
    static constexpr SceneTraits traits{.reference = ReferenceKind::odeint, .torque_depends_on_orientation = true};
    DipoleTop() {
        params.declare("inertia", {1.0, 1.5, 2.0}, "kg m^2", "principal moments I'1, I'2, I'3");
        params.declare("dipole", {0.0, 0.0, 1.0}, "A m^2", "magnetic dipole moment, body frame");
        params.declare("field", {0.0, 0.0, 1.0}, "T", "uniform magnetic field, world frame");
        params.declare("omega0", {0.5, -0.3, 1.0}, "rad/s", "initial angular velocity, body frame");
        params.declare("q0", {std::cos(0.5), std::sin(0.5), 0.0, 0.0}, "-",
                       "initial orientation (w, x, y, z), body to world (default: 1 rad about x)");
        params.declare("t_end", {10.0}, "s", "duration");
    }

    void prepare() override {
        inertia_ = params.principal_moments("inertia");
        dipole_ = params.vec3("dipole");
        field_ = params.vec3("field");
        params.positive("t_end");
    }

    Bodies initial_state() const override {
        return single_body(1.0, inertia_, params.quat("q0"), params.vec3("omega0"));  // the mass plays no part
    }
    std::vector<double> default_dts() const override { return halving_ladder(1e-2, 7); }
    std::vector<double> quick_dts() const override { return halving_ladder(1e-2, 4); }

    void evaluate_forces(Bodies& b, double) const override {
        b.force.set(0, Vec3::Zero());
        b.torque.set(0, to_world(b.orientation[0], dipole_).cross(field_));
    }

    double energy(const Bodies& b) const override { return rotational_energy(b) + potential(b); }
    std::vector<std::pair<std::string, double>> energy_parts(const Bodies& b) const override {
        return {{"rotational", rotational_energy(b)}, {"potential", potential(b)}};
    }

    std::optional<TorqueLaw> torque_law() const override { return TorqueLaw{"dipole", {{"dipole_body", dipole_}, {"field_world", field_}}}; }

private:
    double potential(const Bodies& b) const { return -to_world(b.orientation[0], dipole_).dot(field_); }
    Vec3 inertia_, dipole_, field_;
};

const RegisterScene<DipoleTop> registration(
    "dipole_top", "asymmetric body with a dipole in a uniform field, T = mu x B, I' = (1, 1.5, 2), 10 s",
    "orientation-dependent torque; reference by Odeint");

}  // namespace
}  // namespace rotbench
