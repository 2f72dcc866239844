// `fibre_bounce`: seed 000, test case 2 (Zhao & van Wachem's fibre) with the geometry of
// the CIMNE reproduction (the seed omits it): five spheres of radius 0.5 at body x = -1 ... 1 (step
// 0.5), all scaled by 0.012516777 m; mass 2.15710e-3 kg; principal moments 4.01318e-8
// (axial, body x) and 2.21899e-7 kg m^2; Hertz normal contact of each sphere with the
// floor z = 0 (fibre E = 5e7 Pa, nu = 0.35; floor E = 5e7 Pa, nu = 0.23), no friction, no
// damping; gravity 9.81 m/s^2; centre 0.5 m above the floor, axis tilted 30 degrees from
// horizontal in the vertical x-z plane. The true motion conserves the total energy
// (translational + rotational + potential + elastic) exactly.
#include "harness/scenes/scene.hpp"
#include "harness/scenes/single_body.hpp"
#include "schemes/quaternion.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace rotbench {
namespace {

class FibreBounce final : public Scene {
public:
    FibreBounce() {
        params.declare("scale", {0.012516777}, "m", "length unit of the cluster geometry");
        params.declare("mass", {2.15710e-3}, "kg", "mass");
        params.declare("inertia", {4.01318e-8, 2.21899e-7, 2.21899e-7}, "kg m^2", "principal moments (axial first)");
        params.declare("young", {5e7}, "Pa", "Young's modulus of the fibre");
        params.declare("poisson", {0.35}, "-", "Poisson's ratio of the fibre");
        params.declare("floor_young", {5e7}, "Pa", "Young's modulus of the floor");
        params.declare("floor_poisson", {0.23}, "-", "Poisson's ratio of the floor");
        params.declare("gravity", {9.81}, "m/s^2", "gravitational acceleration (along -z)");
        params.declare("height", {0.5}, "m", "initial height of the centre of mass");
        params.declare("tilt", {30.0}, "deg", "initial angle of the axis below the horizontal");
        params.declare("omega0", {0.0, 0.0, 0.0}, "rad/s", "initial angular velocity, body frame");
        params.declare("t_end", {1.0}, "s", "duration");
    }

    void prepare() override {
        const double scale = params.positive("scale");
        mass_ = params.positive("mass");
        inertia_ = params.principal_moments("inertia");
        radius_ = 0.5 * scale;
        for (int k = 0; k < 5; ++k) offsets_[k] = (k - 2) * 0.5 * scale;
        auto compliance = [&](const char* young, const char* poisson) {
            const double nu = params.number(poisson);
            params.require(nu > -1.0 && nu < 0.5, poisson, "must lie in (-1, 0.5)");
            return (1.0 - nu * nu) / params.positive(young);
        };
        effective_modulus_ = 1.0 / (compliance("young", "poisson") + compliance("floor_young", "floor_poisson"));
        gravity_ = params.number("gravity");
        params.require(gravity_ >= 0.0, "gravity", "must not be negative");
        params.positive("height");
        params.positive("t_end");
    }

    Bodies initial_state() const override {
        const Quat q0(Eigen::AngleAxisd(params.number("tilt") * std::numbers::pi / 180.0, Vec3::UnitY()));
        return single_body(mass_, inertia_, q0, params.vec3("omega0"), Vec3(0.0, 0.0, params.number("height")));
    }
    // A ladder by halving from 1e-5, and the seed's Figs. 9-11 steps, 1e-5 and 1e-7.
    std::vector<double> default_dts() const override { return halving_ladder(1e-5, 6, {1e-7}); }
    std::vector<double> quick_dts() const override { return halving_ladder(1e-5, 3); }

    // The spheres lie on the body x axis, so one rotation of that axis places all five:
    // this runs at every step, and five quaternion rotations would be most of it.
    void evaluate_forces(Bodies& b, double) const override {
        const Vec3 axis = fibre_axis(b);
        const double centre_z = b.position[0].z();
        Vec3 force(0.0, 0.0, -mass_ * gravity_), torque = Vec3::Zero();
        if (touches_floor(centre_z, axis.z())) {
            for (const double offset : offsets_) {
                const double overlap = radius_ - (centre_z + offset * axis.z());
                if (overlap <= 0.0) continue;
                const Vec3 arm = offset * axis;
                // Hertz: F = 4/3 E* sqrt(R) delta^(3/2), normal to the floor.
                const Vec3 contact(0.0, 0.0, 4.0 / 3.0 * effective_modulus_ * std::sqrt(radius_) * overlap * std::sqrt(overlap));
                force += contact;
                torque += arm.cross(contact);
            }
        }
        b.force.set(0, force);
        b.torque.set(0, torque);
    }

    // No per-step reference: the motion is chaotic after the first bounces, and a sampled
    // trajectory at dt = 1e-7 would take gigabytes. The scene's physics is checked instead
    // by Odeint conserving its energy (tests/test_scenes.cpp).
    std::vector<double> contact_gaps(const Bodies& b) const override {
        const Vec3 axis = fibre_axis(b);
        std::vector<double> gaps;
        for (const double offset : offsets_) gaps.push_back(b.position[0].z() + offset * axis.z() - radius_);
        return gaps;
    }
    // energy() runs at every step of a run; it adds the parts of the one body without
    // building their names.
    double energy(const Bodies& b) const override {
        return translational_energy(b, 0) + rotational_energy(b, 0) + potential(b) + elastic(b);
    }
    std::vector<std::pair<std::string, double>> energy_parts(const Bodies& b) const override {
        return {{"translational", translational_energy(b)},
                {"rotational", rotational_energy(b)},
                {"potential", potential(b)},
                {"elastic", elastic(b)}};
    }

private:
    // The body x axis in the world frame: to_world(q, e_x) (schemes/quaternion.hpp) written out
    // without its products by the zero components of e_x. Those products are exact (0 for a
    // finite q), so the bits are the same, but GCC may not drop them itself (0 * x is NaN for an
    // infinite x). It runs twice per step, in the forces and in the energy.
    ROTBENCH_INLINE static Vec3 fibre_axis(const Bodies& b) {
        const Quat q = b.orientation[0];
        const double s = 2.0 / q.squaredNorm();
        return {1.0 + s * (-(q.y() * q.y()) - q.z() * q.z()), s * (q.w() * q.z() + q.x() * q.y()),
                s * (q.x() * q.z() - q.w() * q.y())};
    }
    // Whether the lowest sphere overlaps the floor. Its overlap is the largest of the five, bit for
    // bit: the offsets are symmetric (offsets_[0] = -offsets_[4] exactly), and rounding keeps the
    // order of the products and sums. In flight, most of a run, the two loops over the spheres
    // (forces and energy) are then skipped with the same results.
    bool touches_floor(double centre_z, double axis_z) const {
        return radius_ - (centre_z - std::abs(offsets_.back() * axis_z)) > 0.0;
    }
    double potential(const Bodies& b) const { return mass_ * gravity_ * b.position[0].z(); }
    double elastic(const Bodies& b) const {  // Hertz potential: 8/15 E* sqrt(R) delta^(5/2)
        const double axis_z = fibre_axis(b).z();
        double e = 0.0;
        if (!touches_floor(b.position[0].z(), axis_z)) return e;
        for (const double offset : offsets_) {
            const double overlap = radius_ - (b.position[0].z() + offset * axis_z);
            if (overlap > 0.0) e += 8.0 / 15.0 * effective_modulus_ * std::sqrt(radius_) * overlap * overlap * std::sqrt(overlap);
        }
        return e;
    }

    double mass_ = 0, radius_ = 0, effective_modulus_ = 0, gravity_ = 0;
    Vec3 inertia_;
    std::array<double, 5> offsets_;  // sphere centres on the body x axis
};

const RegisterScene<FibreBounce> registration(
    "fibre_bounce", "five-sphere fibre falling from 0.5 m onto a Hertz floor, no friction, no damping, 1 s",
    "Irazabal et al., seed 000, section 3.1.2 (after Zhao & van Wachem); geometry of the CIMNE reproduction",
    "How the torque enters each seed scheme decides its energy error here, where contact torques drive the rotation: "
    "direct averages T^n and T^{n+1} (eqs. 36, 43), a second-order treatment; munjiza_rk4 uses T^n alone (eq. 44), "
    "zvw T^n and zvw_corrected T^{n+1} alone (eq. 63), first order. The slopes below measure it.");

}  // namespace
}  // namespace rotbench
