// `richardson`: the orientation update of LAMMPS fix rigid (MathExtra::richardson) and
// LIGGGHTS multisphere, from Kamberaj, Low & Neal, J. Chem. Phys. 122:224114 (2005).
//
// After the half kick of L, dq/dt = 1/2 w q is advanced over dt by one explicit Euler step
// and by two half steps (w recomputed from L at the middle), each normalised; the
// Richardson combination 2 q_two_halves - q_one_step cancels the O(dt^2) local error of
// Euler, and the result is normalised again. As in fix rigid, every w comes from L through
// the body axes of its q (schemes/quaternion.hpp, body_axes).
#include "schemes/kick_drift_kick.hpp"

namespace rotbench {
namespace {

// q + h (1/2 w q), normalised: one explicit Euler step of dq/dt = 1/2 w q.
template <class S>
ROTBENCH_INLINE QuatT<S> euler_step(const QuatT<S>& q, const Vec3T<S>& omega, double h) {
    return normalized(QuatT<S>(q.coeffs() + (0.5 * h) * pure_times<S>(omega, q)));
}

struct RichardsonRotation : UnitResult {
    template <class S>
    static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, const BodyAxesT<S>& axes, double dt) {
        const QuatT<S>& q = start.q;
        const Vec3T<S> inverse_inertia = start.inertia.cwiseInverse();
        const Vec3T<S> omega = omega_from_momentum(axes, inverse_inertia, momentum);
        const QuatT<S> one_step = euler_step(q, omega, dt);
        const QuatT<S> half = euler_step(q, omega, 0.5 * dt);
        const Vec3T<S> omega_half = omega_from_momentum(body_axes<true>(half), inverse_inertia, momentum);
        const QuatT<S> two_halves = euler_step(half, omega_half, 0.5 * dt);
        return normalized(QuatT<S>(2.0 * two_halves.coeffs() - one_step.coeffs()));
    }
};

const RegisterScheme<KickDriftKick<RichardsonRotation>> registration(
    "richardson", "Richardson-extrapolated quaternion update (LAMMPS fix rigid, LIGGGHTS multisphere)",
    "Kamberaj, Low & Neal, J. Chem. Phys. 122:224114 (2005); LAMMPS MathExtra::richardson",
    "Kick of L with T^n, then q advanced by 2 q(two Euler half steps) - q(one Euler step), w recomputed from L at "
    "the half step, each normalised; kick with T^{n+1}. w from L through the body axes of q. "
    "Not symplectic and not time-reversible.",
    kick_drift_kick_claims({.order = {2, "the extrapolation cancels the O(dt^2) local error of the Euler steps: second order"}}));

}  // namespace
}  // namespace rotbench
