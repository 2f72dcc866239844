// The probe scheme of a ROTBENCH_PROBES build: a scheme added as a new contributor adds one,
// in one file, with an id that sorts before every other. The whole suite must pass with it
// (CI builds and tests it), so no test may list scheme ids by hand.
//
// Kick of L with T^n; q^{n+1} = exp(dt w_mid) q^n with w_mid from L^{n+1/2} at the explicit
// mid-point exp(dt/2 w^n) q^n; kick with T^{n+1}. Second order, keeps L without torque.
#include "schemes/kick_drift_kick.hpp"

namespace rotbench {
namespace {

struct ProbeRotation {
    template <class S>
    static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, double dt) {
        const QuatT<S> q_mid = rotation_increment<S>(start.omega, 0.5 * dt) * start.q;
        return rotation_increment<S>(omega_from_momentum(q_mid, start.inertia, momentum), dt) * start.q;
    }
};

const RegisterScheme<KickDriftKick<ProbeRotation>> registration(
    "aaa_probe", "probe: explicit mid-point rotation with exponential maps (ROTBENCH_PROBES builds only)",
    "probe (tests/probes/probe_scheme.cpp)",
    "Kick of L with T^n; q^{n+1} = exp(dt w_mid) q^n with w_mid from L^{n+1/2} at exp(dt/2 w^n) q^n; kick with T^{n+1}.",
    {.without_torque = {2, "explicit mid-point rule on the rotation at constant L: second order"},
     .with_torque = {2, "trapezoidal kicks around a second-order rotation: second order"},
     .conserves_momentum = true});

}  // namespace
}  // namespace rotbench
