// `rozmanov_kusalik`: the rotational velocity-Verlet integrator of Rozmanov & Kusalik,
// Phys. Rev. E 81:056706 (2010) (their RVV1).
//
// Our reading: after the half kick of L, the orientation turns at a constant angular
// velocity w_mid by the exact exponential map, q^{n+1} = exp(dt w_mid) q^n, where w_mid is the
// angular velocity at the middle of that very rotation,
//   w_mid = I(q_mid)^-1 L^{n+1/2},   q_mid = exp(dt/2 w_mid) q^n,
// found by fixed-point iteration to round-off. Replaying the step backwards from q^{n+1}
// finds the same q_mid and w_mid, so the map is time-reversible; |q| = 1 is kept.
#include "schemes/kick_drift_kick.hpp"

namespace rotbench {
namespace {

struct RozmanovKusalikRotation {
    template <class S>
    static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, const BodyAxesT<S>& axes, double dt) {
        const QuatT<S>& q = start.q;
        const auto midpoint = [&](const Vec3T<S>& w) { return QuatT<S>(rotation_increment<S>(w, 0.5 * dt) * q); };
        return rotation_increment<S>(midpoint_angular_velocity(start, momentum, axes, midpoint, "rozmanov_kusalik"), dt) * q;
    }
};

const RegisterScheme<KickDriftKick<RozmanovKusalikRotation>> registration(
    "rozmanov_kusalik", "Rozmanov & Kusalik rotational velocity Verlet (implicit mid-step angular velocity)",
    "Rozmanov & Kusalik, Phys. Rev. E 81:056706 (2010)",
    "Our reading of RVV1: kick of L with T^n; q^{n+1} = exp(dt w_mid) q^n with w_mid = I(q_mid)^-1 L^{n+1/2} at "
    "q_mid = exp(dt/2 w_mid) q^n, iterated to round-off; kick with T^{n+1}. A step where the iteration does not "
    "converge in 100 passes is recorded as a failed run.",
    kick_drift_kick_claims({.order = {2, "a time-reversible mid-point rotation at constant L: second order"}, .symmetric = true}));

}  // namespace
}  // namespace rotbench
