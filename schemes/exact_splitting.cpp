// `exact_splitting`: kick - exact free-rigid-body flow - kick (van Zon & Schofield, J. Comput.
// Phys. 225:145, 2007; Celledoni, Fasso, Safstrom & Zanna, SIAM J. Sci. Comput. 30:2084, 2008).
//
// The free rotation over dt is the closed-form torque-free motion (Jacobi elliptic
// functions and Carlson's R_J) that also serves as the harness's reference: it lives once,
// in references/free_rigid_body. Without torque the scheme is exact; with torque it is the
// symplectic Strang splitting of kinetic and potential parts.
#include "schemes/detail/free_rigid_body.hpp"
#include "schemes/kick_drift_kick.hpp"

namespace rotbench {
namespace {

struct ExactFreeRotation {
    static Quat rotate(const RigidBody& start, const Vec3& momentum, double dt) {
        const Quat q = start.q.normalized();
        const Vec3 omega_body = to_body(q, momentum).cwiseQuotient(start.inertia);
        return FreeRigidBody(start.inertia, q, omega_body).orientation(dt);
    }
#if ROTBENCH_SIMD
    // The closed form branches on each body's motion (steady, symmetric, which axis the momentum
    // circulates about): a pack steps its bodies one by one.
    static QuatT<Pack> rotate(const RigidBodyT<Pack>& start, const Vec3T<Pack>& momentum, double dt) {
        return each_body(start, momentum, [dt](const RigidBody& b, const Vec3& l) { return rotate(b, l, dt); });
    }
#endif
};

const RegisterScheme<KickDriftKick<ExactFreeRotation>> registration(
    "exact_splitting", "Kick - exact free-rigid-body flow - kick (elliptic functions every step)",
    "van Zon & Schofield, J. Comput. Phys. 225:145 (2007); Celledoni et al., SIAM J. Sci. Comput. 30:2084 (2008)",
    "Kick of L with T^n, the closed-form torque-free rotation over dt (references/free_rigid_body, verified "
    "against Odeint), kick with T^{n+1}. Exact without torque; symplectic Strang splitting with it.",
    {.with_torque = {2, "Strang splitting of the exact free flow and the torque kicks: second order"},
     .exact_without_torque = true,
     .conserves_momentum = true,
     .bounded_energy = true,
     .time_reversible = true});

}  // namespace
}  // namespace rotbench
