// `fincham`: Fincham's rotational leapfrog, Mol. Simul. 8:165 (1992), the rule Yade's aspherical
// integrator cites (NewtonIntegrator::leapfrogAsphericalRotate; Yade 2023.02a, as shipped, reads
// it at first order: docs/clients.md).
//
// Written in the synchronous (kick-drift-kick) form, which gives the same L and q as the
// leapfrog one. The orientation is advanced by the explicit mid-point rule on
// dq/dt = 1/2 w q: a half step with w^n = I(q^n)^-1 L^n to q^{n+1/2}, then the full step with
// w^{n+1/2} = I(q^{n+1/2})^-1 L^{n+1/2}, and a normalisation.
#include "schemes/kick_drift_kick.hpp"

namespace rotbench {
namespace {

struct FinchamRotation : UnitResult {
    template <class S>
    static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, double dt) {
        const QuatT<S>& q = start.q;
        const QuatT<S> half(q.coeffs() + (0.25 * dt) * pure_times<S>(start.omega, q));
        const Vec3T<S> omega_half = omega_from_momentum(body_axes(half), start.inertia.cwiseInverse(), momentum);
        return normalized(QuatT<S>(q.coeffs() + (0.5 * dt) * pure_times<S>(omega_half, half)));
    }
};

const RegisterScheme<KickDriftKick<FinchamRotation>> registration(
    "fincham", "Fincham's rotational leapfrog (the rule Yade's aspherical integrator cites)",
    "Fincham, Mol. Simul. 8:165 (1992); Allen & Tildesley, Computer Simulation of Liquids, sec. 3.3",
    "Synchronous form of the leapfrog: kick of L with T^n, explicit mid-point rule on dq/dt = 1/2 w q (half step "
    "with w^n, full step with w^{n+1/2} from L^{n+1/2} at q^{n+1/2}), normalisation, kick with T^{n+1}.",
    kick_drift_kick_claims({.order = {2, "the explicit mid-point rule on q at constant L: second order"}}));

}  // namespace
}  // namespace rotbench
