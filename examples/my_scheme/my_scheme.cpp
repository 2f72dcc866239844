// An out-of-tree scheme, written exactly as an in-tree one: a rotation policy, and one
// registration with the scheme's id, citation, reading and claims. Built as a plug-in by
// rotbench_add_scheme() (see CMakeLists.txt here) and run with
//   rotbench run --plugin ./my_scheme.so --schemes exp_midpoint
//
// The scheme: kick of L with T^n, then q^{n+1} = exp(dt w_mid) q^n, with w_mid the angular
// velocity at the explicit mid-point q_mid = exp(dt/2 w^n) q^n (Fincham's rule with exact
// exponential maps instead of additive updates), then kick with T^{n+1}.
#include "schemes/kick_drift_kick.hpp"

namespace {

using namespace rotbench;

struct ExpMidpointRotation {
    static Quat rotate(const RigidBody& start, const Vec3& momentum, double dt) {
        const Quat q_mid = rotation_increment(start.omega, 0.5 * dt) * start.q;
        return rotation_increment(omega_from_momentum(q_mid, start.inertia, momentum), dt) * start.q;
    }
};

const RegisterScheme<KickDriftKick<ExpMidpointRotation>> registration(
    "exp_midpoint", "example plug-in: explicit mid-point rotation with exponential maps",
    "examples/my_scheme (after Fincham, Mol. Simul. 8:165, 1992)",
    "Kick of L with T^n; q^{n+1} = exp(dt w_mid) q^n with w_mid from L^{n+1/2} at exp(dt/2 w^n) q^n; kick with T^{n+1}.",
    {.without_torque = {2, "explicit mid-point rule on the rotation at constant L: second order"},
     .with_torque = {2, "trapezoidal kicks around a second-order rotation: second order"},
     .conserves_momentum = true});

}  // namespace
