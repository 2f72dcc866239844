// `spiral`: SPIRAL, del Valle, Angelidakis, Roy, Munoz & Kozicki, Comput. Phys. Commun.
// 297:109077 (2024); Yade's aspherical integrator after 2023.02a (which, as Debian ships it, still
// has leapfrogAsphericalRotate: docs/clients.md). Synchronous (non-leapfrog)
// form, as in the authors' JaxDEM code:
//   q^{n+1} = q^n exp(dt/2 w'^n) exp(dt^2/4 dw'^n/dt)     (half-angle exponentials, body frame)
//   w'^{n+1} = w'^n + (k1 + k2 + 4 k3)/6                  (SSPRK3 on Euler's equations)
//   k1 = dt f(w'^n), k2 = dt f(w'^n + k1), k3 = dt f(w'^n + (k1 + k2)/4),  f = I^-1 (T' - w' x I w'),
// all with the torque of the start of the step, taken to the body frame at q^n. The step
// uses T^n only, so everything happens in the predictor; the corrector has nothing to do.
#include "schemes/quaternion.hpp"
#include "schemes/scheme.hpp"

namespace rotbench {
namespace {

template <class S = double>
struct Spiral {
    template <class T>
    using rebind = Spiral<T>;
    struct Memory {};

    static void start(const RigidBodyT<S>&, Memory&) {}

    static void predict(RigidBodyT<S>& b, Memory&, double dt) {
        const Vec3T<S> omega = to_body(b.q, b.omega);
        const Vec3T<S> torque = to_body(b.q, b.torque);
        const auto f = [&](const Vec3T<S>& w) { return euler_acceleration(w, torque, b.inertia); };
        const Vec3T<S> k1 = dt * f(omega);
        // exp(dt/2 w) is the rotation by dt |w|: half-angle convention of the paper.
        b.q = b.q * rotation_from_vector<S>(dt * omega) * rotation_from_vector<S>(0.5 * dt * k1);
        const Vec3T<S> k2 = dt * f(omega + k1);
        const Vec3T<S> k3 = dt * f(omega + 0.25 * (k1 + k2));
        b.omega = to_world(b.q, omega + (k1 + k2 + 4.0 * k3) / 6.0);
    }

    static void correct(RigidBodyT<S>&, Memory&, double) {}
};

const RegisterScheme<Spiral<>> registration(
    "spiral", "SPIRAL: two exponential maps and SSPRK3 on Euler's equations (Yade after 2023.02a)",
    "del Valle et al., Comput. Phys. Commun. 297:109077 (2024); synchronous form as in JaxDEM's Spiral",
    "q^{n+1} = q^n exp(dt/2 w'^n) exp(dt^2/4 dw'/dt) (half-angle exponentials, body frame), w' by SSPRK3; the "
    "torque is T^n throughout (one force evaluation, at the start of the step), so the corrector does nothing. "
    "No normalisation: the product of unit quaternions stays unit to round-off.",
    {.without_torque = {2, "the paper's third order holds for the body-frame w' (SSPRK3 on Euler's equations, which do "
                           "not involve q without torque) but not for q: the two exponentials miss the dt^3 commutator "
                           "term of the rotation (Magnus), so q, and the world w = q w' q*, are second order"},
     .with_torque = {1, "the torque of the start of the step is held over the whole step: first order"}});

}  // namespace
}  // namespace rotbench
