// The torque-free rigid body integrated by Boost.Odeint in long double (eps ~ 1e-19) at
// tolerance 1e-18, so that the integrator's own error is far below the round-off of the
// double-precision solutions it judges. GCC 12 reports Odeint's stepper copy constructor as
// reading uninitialised buffers (a false positive; the buffers are resized before use).
#pragma once
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "schemes/bodies.hpp"

#include <array>
#include <boost/numeric/odeint.hpp>

namespace rotbench::testing {

using Real = long double;
using OdeState = std::array<Real, 7>;  // w'1, w'2, w'3, qw, qx, qy, qz

// Euler's equations and q' = q w'/2.
struct EulerEquations {
    std::array<Real, 3> I;
    void operator()(const OdeState& s, OdeState& d, Real) const {
        const Real w0 = s[0], w1 = s[1], w2 = s[2], qw = s[3], qx = s[4], qy = s[5], qz = s[6];
        d[0] = (I[1] - I[2]) / I[0] * w1 * w2;
        d[1] = (I[2] - I[0]) / I[1] * w2 * w0;
        d[2] = (I[0] - I[1]) / I[2] * w0 * w1;
        d[3] = 0.5L * (-qx * w0 - qy * w1 - qz * w2);  // q (0, w') / 2
        d[4] = 0.5L * (qw * w0 + qy * w2 - qz * w1);
        d[5] = 0.5L * (qw * w1 + qz * w0 - qx * w2);
        d[6] = 0.5L * (qw * w2 + qx * w1 - qy * w0);
    }
};

inline auto odeint_stepper() {
    return boost::numeric::odeint::make_controlled<boost::numeric::odeint::runge_kutta_fehlberg78<OdeState, Real>>(1e-18L, 1e-18L);
}

// The orientation at t of the body that starts at q0 with body-frame angular momentum l,
// w = l / I taken in long double.
inline Quat odeint_orientation(const Vec3& inertia, const Quat& q0, const Vec3& l, double t) {
    OdeState s{Real(l.x()) / inertia.x(), Real(l.y()) / inertia.y(), Real(l.z()) / inertia.z(), q0.w(), q0.x(), q0.y(), q0.z()};
    boost::numeric::odeint::integrate_adaptive(odeint_stepper(), EulerEquations{{inertia.x(), inertia.y(), inertia.z()}}, s,
                                               Real(0), Real(t), Real(t) / 16);
    return Quat(double(s[3]), double(s[4]), double(s[5]), double(s[6])).normalized();
}

}  // namespace rotbench::testing
