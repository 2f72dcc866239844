// `torqued_cylinder`: a steel cylinder (rho = 7750 kg/m^3, R = 0.05 m, H = 0.15 m) under a
// constant torque tau = 0.025 N m along its body axis, w0 = (0.3, -0.9, 0.6) rad/s (body).
// Angular velocity in closed form: w'z = w'z0 + (tau/I_a) t, and (w'x + i w'y) turns by
// -kappa Phi(t), kappa = (I_t - I_a)/I_t, Phi = int w'z dt = w'z0 t + tau t^2 / (2 I_a).
// The orientation has no elementary closed form: it comes from Odeint.
#include "harness/scenes/scene.hpp"
#include "harness/scenes/single_body.hpp"
#include "schemes/quaternion.hpp"


namespace rotbench {
namespace {

class TorquedCylinder final : public Scene {
public:
    static constexpr SceneTraits traits{.reference = ReferenceKind::odeint};
    TorquedCylinder() {
        params.declare("density", {7750.0}, "kg/m^3", "density");
        params.declare("radius", {0.05}, "m", "cylinder radius");
        params.declare("height", {0.15}, "m", "cylinder height (along body z)");
        params.declare("torque", {0.025}, "N m", "constant torque about the body z axis");
        params.declare("omega0", {0.3, -0.9, 0.6}, "rad/s", "initial angular velocity, body frame");
        params.declare("q0", {1.0, 0.0, 0.0, 0.0}, "-", "initial orientation (w, x, y, z), body to world");
        params.declare("t_end", {5.0}, "s", "duration");
    }

    void prepare() override {
        cylinder_ = solid_cylinder(params);
        torque_ = params.number("torque");
        params.positive("t_end");
    }

    Bodies initial_state() const override {
        return single_body(cylinder_.mass, cylinder_.inertia, params.quat("q0"), params.vec3("omega0"));
    }
    std::vector<double> default_dts() const override { return halving_ladder(1e-2, 7); }
    std::vector<double> quick_dts() const override { return halving_ladder(1e-2, 4); }

    void evaluate_forces(Bodies& b, double) const override {
        b.force.set(0, Vec3::Zero());
        b.torque.set(0, to_world(b.orientation[0], Vec3(0.0, 0.0, torque_)));  // body-fixed torque
    }

    bool conserves_energy() const override { return false; }  // the torque does work
    std::optional<TorqueLaw> torque_law() const override { return TorqueLaw{"body_constant", {{"torque_body", Vec3(0.0, 0.0, torque_)}}}; }
    bool gains_energy() const override { return true; }
    std::optional<Vec3> exact_omega_body(std::size_t, double t) const override {
        const Vec3 w0 = params.vec3("omega0");
        const double it = cylinder_.inertia.x(), ia = cylinder_.inertia.z();
        const double kappa = (it - ia) / it, phi = w0.z() * t + 0.5 * torque_ * t * t / ia;
        const double c = std::cos(kappa * phi), s = std::sin(kappa * phi);
        return Vec3(c * w0.x() + s * w0.y(), -s * w0.x() + c * w0.y(), w0.z() + torque_ / ia * t);
    }

private:
    SolidCylinder cylinder_{};
    double torque_ = 0;
};

const RegisterScene<TorquedCylinder> registration(
    "torqued_cylinder", "steel cylinder under a constant axial body torque, w0 = (0.3, -0.9, 0.6) rad/s, 5 s",
    "closed-form w (Euler's equations with I'x = I'y); orientation by Odeint");

}  // namespace
}  // namespace rotbench
