// What the one-body scenes build alike: the body itself, and the solid cylinder.
#pragma once

#include "harness/scenes/params.hpp"
#include "schemes/bodies.hpp"

#include <numbers>

namespace rotbench {

// One body; the angular velocity is given in the body frame, as the scene keys are.
inline Bodies single_body(double mass, const Vec3& inertia, const Quat& q0, const Vec3& omega0_body,
                          const Vec3& position = Vec3::Zero()) {
    Bodies b;
    b.resize(1);
    b.mass[0] = mass;
    b.inertia.set(0, inertia);
    b.orientation.set(0, q0);
    b.omega.set(0, q0 * omega0_body);
    b.position.set(0, position);
    return b;
}

struct SolidCylinder {
    double mass;
    Vec3 inertia;  // (I_t, I_t, I_a), axis along body z
};

// From the keys `density`, `radius`, `height` (each checked > 0).
inline SolidCylinder solid_cylinder(const Params& p) {
    const double r = p.positive("radius"), h = p.positive("height");
    const double mass = p.positive("density") * std::numbers::pi * r * r * h;
    const double transverse = mass * (3.0 * r * r + h * h) / 12.0;
    return {mass, Vec3(transverse, transverse, 0.5 * mass * r * r)};
}

}  // namespace rotbench
