// `cylinder_free`: seed 000, test case 1 (Munjiza et al.'s free cylinder). A cylinder of
// radius 0.5 m, height 1.5 m and density 1 (so I'z/I'x = 0.5) spins freely with
// w0 = (0, 1, 100) rad/s in both frames (q0 = identity) for 0.5 s. No force, no torque.
// Exact answer: w'x = sin 50t, w'y = cos 50t, w'z = 100 (the seed's eq. 65b prints sin
// for w'y; cos is what Euler's equations give for this start) and the closed-form
// orientation of FreeSymmetricTop.
#include "harness/scene.hpp"
#include "references/free_symmetric_top.hpp"

#include <numbers>

namespace rotbench {
namespace {

class CylinderFree final : public Scene {
public:
    static constexpr double radius = 0.5, height = 1.5, density = 1.0;

    CylinderFree()
        : mass_(density * std::numbers::pi * radius * radius * height),
          inertia_transverse_(mass_ * (3.0 * radius * radius + height * height) / 12.0),
          inertia_axial_(0.5 * mass_ * radius * radius),
          omega0_(0.0, 1.0, 100.0),
          exact_(inertia_transverse_, inertia_axial_, Quat::Identity(), omega0_) {}

    Bodies initial_state() const override {
        Bodies b;
        b.resize(1);
        b.mass[0] = mass_;
        b.inertia.set(0, Vec3(inertia_transverse_, inertia_transverse_, inertia_axial_));
        b.omega.set(0, omega0_);  // q0 = identity: body and world frames coincide
        return b;
    }
    double default_t_end() const override { return 0.5; }
    std::vector<double> default_dts() const override { return {1e-2, 1e-3, 1e-4, 1e-5, 1e-6}; }  // Table 1

    void evaluate_forces(Bodies& b, double) const override {
        b.force.set(0, Vec3::Zero());
        b.torque.set(0, Vec3::Zero());
    }

    bool has_reference() const override { return true; }
    ReferenceState reference(std::size_t, double t) const override {
        return {exact_.orientation(t), exact_.omega_world(t)};
    }
    bool conserves_angular_momentum() const override { return true; }

private:
    double mass_, inertia_transverse_, inertia_axial_;
    Vec3 omega0_;
    FreeSymmetricTop exact_;
};

const RegisterScene<CylinderFree> registration(
    "cylinder_free", "torque-free cylinder, I'z/I'x = 0.5, w0 = (0, 1, 100) rad/s, 0.5 s (seed test case 1)",
    "Irazabal et al., seed 000, section 3.1.1 and Table 1 (after Munjiza et al.)");

}  // namespace
}  // namespace rotbench
