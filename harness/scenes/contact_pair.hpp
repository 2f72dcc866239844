// Two bodies in one linear spring-dashpot contact, for the stability study (Peng et al.,
// seed 004, eq. 29): the two material points that touch at t = 0 (anchors a1, a2 in the
// body frames) are joined by a spring of stiffness k_n along the contact normal n (fixed,
// world x) and k_s across it, with dashpots c_n, c_s on their relative velocity:
//     F_2 = -(k_n u_n + k_s u_t) - (c_n u'_n + c_s u'_t),  F_1 = -F_2,  u = p_2 - p_1.
// Linear in the displacements, as the amplification-matrix analysis requires, and
// conservative when undamped. The damping is given as a ratio zeta of the critical damping
// of seed eq. 37, c = 2 zeta sqrt(k / A_max), with k_n = k_s = k and c_n = c_s = c.
// The bodies start at rest but for a small relative velocity that excites every mode.
#pragma once

#include "harness/scenes/scene.hpp"
#include "harness/scenes/stability_probe.hpp"
#include "references/critical_time_step.hpp"
#include "schemes/quaternion.hpp"

#include <string>
#include <utility>
#include <vector>

namespace rotbench {

class ContactPairScene : public Scene, public StabilityProbe {
public:
    ContactPairScene() {
        params.declare("stiffness", {1e10}, "N/m", "contact stiffness, normal and tangential (k_n = k_s)");
        params.declare("zeta", {0.0}, "-", "damping ratio: c_n = c_s = 2 zeta sqrt(k / A_max) (seed eq. 37)");
        params.declare("perturbation", {1e-3}, "m/s", "initial relative speed that excites the contact modes");
    }

    void evaluate_forces(Bodies& b, double) const override {
        const Vec3 arm1 = to_world(b.orientation[0], anchor1_), arm2 = to_world(b.orientation[1], anchor2_);
        const Vec3 u = (b.position[1] + arm2) - (b.position[0] + arm1);
        const Vec3 du = (b.velocity[1] + b.omega[1].cross(arm2)) - (b.velocity[0] + b.omega[0].cross(arm1));
        const Vec3 n = Vec3::UnitX();
        const Vec3 un = u.dot(n) * n, dun = du.dot(n) * n;
        const Vec3 f2 = -(stiffness_ * un + stiffness_ * (u - un)) - (damping_ * dun + damping_ * (du - dun));
        b.force.set(0, -f2);
        b.force.set(1, f2);
        b.torque.set(0, arm1.cross(-f2));
        b.torque.set(1, arm2.cross(f2));
    }
    double energy(const Bodies& b) const override { return kinetic_energy(b) + spring_energy(b); }
    std::vector<std::pair<std::string, double>> energy_parts(const Bodies& b) const override {
        return {{"kinetic", kinetic_energy(b)}, {"spring", spring_energy(b)}};
    }
    bool conserves_energy() const override { return damping_ == 0.0; }

    // What the stability study needs to know.
    double stiffness() const { return stiffness_; }
    double damping() const { return damping_; }
    double a_max() const { return a_max_; }
    // Seed 004's prediction for this contact: eq. 46 (eq. 47 when undamped).
    double predicted_limit() const override { return peng::damped(stiffness_, damping_, a_max_); }
    // The scene as a client reads it (harness/exec/contact_client.hpp): the bodies' shape, the
    // touching points in the body frames and the law, in physical terms.
    struct Shape {
        std::string kind;          // "sphere" (size: radius) or "ellipsoid" (size: semi-axes along body x, y, z)
        std::vector<double> size;  // m
    };
    const Shape& shape() const { return shape_; }
    const Vec3& anchor(std::size_t body) const { return body == 0 ? anchor1_ : anchor2_; }
    // The period of the fastest contact mode Peng's analysis assumes, 2 pi / sqrt(k A_max).
    double period() const override { return 2.0 * 3.141592653589793 / std::sqrt(stiffness_ * a_max_); }
    bool linearisable_at_rest() const override { return true; }
    // The textbook Verlet limit 2/w of the normal mode alone, w^2 = k (1/m1 + 1/m2).
    double verlet_normal_limit() const { return peng::verlet_limit(std::sqrt(stiffness_ * 2.0 / mass_)); }

protected:
    // For the derived scene's prepare(): the bodies (body 2 placed along +x), the anchors
    // (the touching points, body frames) and A_max for the damping ratio.
    void set_pair(Shape shape, double mass, const Vec3& inertia, double half_length, const Quat& q2, double gap_axis_length) {
        shape_ = std::move(shape);
        mass_ = mass;
        inertia_ = inertia;
        q2_ = q2;
        separation_ = gap_axis_length;
        anchor1_ = Vec3(half_length, 0.0, 0.0);
        anchor2_ = to_body(q2, Vec3(-half_length, 0.0, 0.0));
        stiffness_ = params.positive("stiffness");
        a_max_ = peng::a_max(half_length, inertia.minCoeff(), mass, half_length, inertia.minCoeff(), mass);
        const double zeta = params.number("zeta");
        params.require(zeta >= 0.0, "zeta", "must not be negative");
        // Past this, Peng's step (eq. 46, about 1/(w zeta)) is far below any step a run can take.
        params.require(zeta <= 1e3, "zeta", "must be at most 1000 (a contact damped a thousand times past critical)");
        damping_ = zeta * peng::critical_damping(stiffness_, a_max_);
        params.positive("t_end");
    }

public:
    Bodies initial_state() const override {
        Bodies b;
        b.resize(2);
        for (std::size_t i = 0; i < 2; ++i) {
            b.mass[i] = mass_;
            b.inertia.set(i, inertia_);
        }
        b.orientation.set(1, q2_);
        b.position.set(1, Vec3(separation_, 0.0, 0.0));
        // A small relative velocity in every direction, and a small spin, to excite every mode.
        const double v = params.number("perturbation");
        b.velocity.set(1, Vec3(-v, 0.7 * v, 0.4 * v));
        b.omega.set(0, Vec3(0.3, -0.2, 0.5) * v / anchor1_.norm());
        return b;
    }

private:
    double mass_ = 0, stiffness_ = 0, damping_ = 0, a_max_ = 0, separation_ = 0;
    Vec3 inertia_, anchor1_, anchor2_;
    Quat q2_;
    Shape shape_;

    double spring_energy(const Bodies& b) const {
        const Vec3 u = (b.position[1] + to_world(b.orientation[1], anchor2_)) - (b.position[0] + to_world(b.orientation[0], anchor1_));
        return 0.5 * stiffness_ * u.squaredNorm();
    }
};

}  // namespace rotbench
