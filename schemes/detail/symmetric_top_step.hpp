// One step of the exact torque-free rotation of a symmetric top (two equal principal moments A,
// the third C about body axis k): L is fixed in space and its body component l_k is constant,
// so w = L/A + (1/C - 1/A) l_k e_k is a constant rate fixed in space plus one fixed in the body,
// and
//     q(dt) = exp(dt L/A) q exp(dt (1/C - 1/A) l_k e_k)
// (Landau & Lifshitz, Mechanics, sec. 33). Two exponential maps and two products: a fraction of
// the Taylor series (free_flow_series.hpp), which the fibre, the cylinders and every other
// axisymmetric body would otherwise sum at every step.
//
// A template on the scalar, with the axis chosen per lane by selects: a body stepped in a pack
// gets the bits it gets alone. A sphere is symmetric about every axis; its body rate is zero.
#pragma once

#include "schemes/quaternion.hpp"

namespace rotbench {

template <class S>
struct SymmetricTopStep {
    QuatT<S> q;                      // q(dt), where symmetric
    decltype(S() == S()) symmetric;  // per lane: two moments equal
};

// q(dt) for bodies at orientation q (unit) with world angular momentum `momentum`, body-frame
// momentum l (the same vector in the body frame) and principal moments `inertia`.
template <class S>
SymmetricTopStep<S> symmetric_top_step(const Vec3T<S>& inertia, const QuatT<S>& q, const Vec3T<S>& momentum,
                                       const Vec3T<S>& l, double dt) {
    // The axis k whose two companions are equal: x, else y, else z.
    const auto about_x = inertia.y() == inertia.z(), about_y = inertia.z() == inertia.x();
    const auto about_z = inertia.x() == inertia.y();
    const auto symmetric = decltype(about_x)(about_x | about_y | about_z);
    if (!any_lane(symmetric)) return {q, symmetric};  // an asymmetric body pays three comparisons
    const S axial = select(about_x, inertia.x(), select(about_y, inertia.y(), inertia.z()));
    const S transverse = select(about_x, inertia.y(), select(about_y, inertia.z(), inertia.x()));
    const S l_axial = select(about_x, l.x(), select(about_y, l.y(), l.z()));
    const S inverse_transverse = 1.0 / transverse;
    const S turn = dt * ((1.0 / axial - inverse_transverse) * l_axial), zero(0.0);
    const Vec3T<S> body_turn(select(about_x, turn, zero), select(about_x, zero, select(about_y, turn, zero)),
                             select(about_x | about_y, zero, turn));
    const QuatT<S> space = rotation_from_vector<S>((dt * inverse_transverse) * momentum);
    return {(space * q) * rotation_from_vector<S>(body_turn), symmetric};
}

}  // namespace rotbench
