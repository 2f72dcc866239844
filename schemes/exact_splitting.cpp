// `exact_splitting`: kick - exact free-rigid-body flow - kick (van Zon & Schofield, J. Comput.
// Phys. 225:145, 2007; Celledoni, Fasso, Safstrom & Zanna, SIAM J. Sci. Comput. 30:2084, 2008).
//
// The free rotation over dt is the exact torque-free motion: for a symmetric top its two
// constant rotations (schemes/detail/symmetric_top_step.hpp); otherwise its Taylor series summed
// to round-off (schemes/detail/free_flow_series.hpp), which needs only what one step needs, or,
// for a step too long for the series, the closed form (Jacobi elliptic functions and Carlson's
// R_J) that also serves as the harness's reference. Without torque the scheme is exact; with
// torque it is the symplectic Strang splitting of kinetic and potential parts.
#include "schemes/detail/free_flow_series.hpp"
#include "schemes/detail/free_rigid_body.hpp"
#include "schemes/detail/symmetric_top_step.hpp"
#include "schemes/kick_drift_kick.hpp"

namespace rotbench {
namespace {

struct ExactFreeRotation {
    static Quat closed_form(const RigidBody& start, const Vec3& momentum, double dt) {
        const Quat q = start.q.normalized();
        return FreeRigidBody(start.inertia, q, to_body(q, momentum).cwiseQuotient(start.inertia)).orientation(dt);
    }
    template <class S>
    static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, double dt) {
        const QuatT<S> q = normalized(start.q);
        const Vec3T<S> l = to_body(q, momentum);
        const SymmetricTopStep<S> top = symmetric_top_step<S>(start.inertia, q, momentum, l, dt);
        if (!any_lane(!top.symmetric)) return top.q;
        const FreeFlowStep<S> series = free_flow_series<S>(start.inertia, q, l, dt);
        const FreeFlowStep<S> step{select(top.symmetric, top.q, series.q), LaneMask<S>(top.symmetric | series.converged)};
        if (!any_lane(!step.converged)) return step.q;
        // The closed form branches on each body's motion (steady, symmetric, which axis the
        // momentum circulates about): the bodies that need it take it one by one.
        if constexpr (std::is_same_v<S, double>) {
            return closed_form(start, momentum, dt);
        } else {
            return select(step.converged, step.q,
                          each_body(start, momentum, [dt](const RigidBody& b, const Vec3& l) { return closed_form(b, l, dt); }));
        }
    }
};

const RegisterScheme<KickDriftKick<ExactFreeRotation>> registration(
    "exact_splitting", "Kick - exact free-rigid-body flow - kick (series to round-off, elliptic functions for long steps)",
    "van Zon & Schofield, J. Comput. Phys. 225:145 (2007); Celledoni et al., SIAM J. Sci. Comput. 30:2084 (2008)",
    "Kick of L with T^n, the exact torque-free rotation over dt (for a symmetric top its two constant rotations; "
    "otherwise the Taylor series of Euler's equations and of the precession rate summed to round-off, or the closed "
    "form, verified against Odeint, when a step is too long for the series), kick with T^{n+1}. Exact without torque; "
    "symplectic Strang splitting with it.",
    kick_drift_kick_claims({.exact = true, .symmetric = true}));

}  // namespace
}  // namespace rotbench
