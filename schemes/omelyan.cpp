// `omelyan`: the implicit quaternion leapfrog of Omelyan, Comput. Phys. 12:97 (1998) (the
// "modified quaternion approach"); Yade's NewtonIntegrator option Omelyan98.
//
// q^{n+1} = [(1 - |u|^2) q^n + 2 u q^n] / (1 + |u|^2),  u = dt w_mid / 4,
// a Cayley-type map that keeps |q| = 1 exactly, with w_mid = I(q_mid)^-1 L^{n+1/2} at the
// mid-point q_mid = (q^n + q^{n+1}) / 2 (normalised): implicit, solved by fixed-point
// iteration to round-off. Time-reversible.
#include "schemes/kick_drift_kick.hpp"

namespace rotbench {
namespace {

template <class S>
QuatT<S> omelyan_step(const QuatT<S>& q, const Vec3T<S>& omega, double dt) {
    const Vec3T<S> u = 0.25 * dt * omega;
    const S u2 = u.squaredNorm();
    return QuatT<S>(((1.0 - u2) * q.coeffs() + (0.5 * dt) * pure_times<S>(omega, q)) / (1.0 + u2));  // 2 u q = dt (1/2 w q)
}

struct OmelyanRotation {
    template <class S>
    static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, const BodyAxesT<S>& axes, double dt) {
        const QuatT<S>& q = start.q;
        const auto midpoint = [&](const Vec3T<S>& w) { return QuatT<S>(q.coeffs() + omelyan_step(q, w, dt).coeffs()); };
        return omelyan_step(q, midpoint_angular_velocity(start, momentum, axes, midpoint, "omelyan"), dt);
    }
};

const RegisterScheme<KickDriftKick<OmelyanRotation>> registration(
    "omelyan", "Omelyan's implicit quaternion leapfrog, norm-preserving (Yade option Omelyan98)",
    "Omelyan, Comput. Phys. 12:97 (1998)",
    "Kick of L with T^n; q^{n+1} = [(1 - |u|^2) q^n + 2 u q^n]/(1 + |u|^2), u = dt w_mid/4, with w_mid from "
    "L^{n+1/2} at the mid-point (q^n + q^{n+1})/2, iterated to round-off; kick with T^{n+1}. A step where the "
    "iteration does not converge in 100 passes is recorded as a failed run.",
    kick_drift_kick_claims({.order = {2, "an implicit mid-point rule on q at constant L, time-reversible: second order"},
                            .symmetric = true}));

}  // namespace
}  // namespace rotbench
