#include "references/free_symmetric_top.hpp"

#include "schemes/quaternion.hpp"

#include <cmath>

namespace rotbench {
namespace {

// exp of the rotation vector `angle * axis_unit`, as a unit quaternion.
Quat rotation_about(const Vec3& rotation_vector) { return rotation_increment(rotation_vector, 1.0); }

}  // namespace

FreeSymmetricTop::FreeSymmetricTop(double inertia_transverse, double inertia_axial, const Quat& q0,
                                   const Vec3& omega0_body)
    : inertia_transverse_(inertia_transverse), q0_(q0.normalized()) {
    const Vec3 inertia(inertia_transverse, inertia_transverse, inertia_axial);
    momentum0_body_ = inertia.cwiseProduct(omega0_body);
    momentum_world_ = to_world(q0_, momentum0_body_);
    body_rate_ = (1.0 / inertia_axial - 1.0 / inertia_transverse) * momentum0_body_.z();
}

Quat FreeSymmetricTop::orientation(double t) const {
    return rotation_about(momentum_world_ * (t / inertia_transverse_)) * q0_ *
           rotation_about(Vec3(0.0, 0.0, body_rate_ * t));
}

Vec3 FreeSymmetricTop::omega_body(double t) const {
    // L'(t) is L'(0) turned about e_z by -c L'_z t.
    const double angle = -body_rate_ * t;
    const double c = std::cos(angle), s = std::sin(angle);
    const Vec3 momentum_body(c * momentum0_body_.x() - s * momentum0_body_.y(),
                             s * momentum0_body_.x() + c * momentum0_body_.y(), momentum0_body_.z());
    return momentum_body / inertia_transverse_ + Vec3(0.0, 0.0, body_rate_);
}

Vec3 FreeSymmetricTop::omega_world(double t) const { return to_world(orientation(t), omega_body(t)); }

}  // namespace rotbench
