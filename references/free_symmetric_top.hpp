// Closed-form motion of a torque-free axisymmetric rigid body (principal moments
// I1 = I2 = It, I3 = Ia, symmetry axis = body z).
//
// With L the constant world angular momentum and c = 1/Ia - 1/It, the body angular
// velocity is w' = L'/It + c L'_z e_z, and the orientation (body -> world) factors into
// a rotation about L in space and a rotation about the symmetry axis in the body:
//     q(t) = exp(t L / (2 It)) q0 exp(t c L'_z e_z / 2).
// Differentiating gives q^-1 dq/dt = w'/2 with w' as above (the body-frame kinematics),
// which the tests also check against Boost.Odeint.
#pragma once

#include "schemes/bodies.hpp"

namespace rotbench {

class FreeSymmetricTop {
public:
    FreeSymmetricTop(double inertia_transverse, double inertia_axial, const Quat& q0, const Vec3& omega0_body);

    Quat orientation(double t) const;
    Vec3 omega_body(double t) const;
    Vec3 omega_world(double t) const;

private:
    double inertia_transverse_;
    Quat q0_;
    Vec3 momentum_world_;   // L
    Vec3 momentum0_body_;   // L'(0)
    double body_rate_;      // c L'_z: rate of the body-frame precession about e_z
};

}  // namespace rotbench
