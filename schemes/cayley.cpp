// `cayley`: a Lie-group variational integrator with the Cayley map as retraction, the
// family of Li et al., Comp. Part. Mech. (2024) (Cayley-map integrators for DEM).
//
// Our reading (the paper's exact discretisation was not available to us): the discrete
// Euler-Poincare equations of the free rigid body with q^{n+1} = q^n cay(dt xi) and the
// discrete Lagrangian dt/2 xi.I xi (Kobilarov & Marsden; Lee, Leok & McClamroch). The body
// momentum at the start of the step, P = I'(q^n)^T L^{n+1/2}, fixes the body velocity xi:
//   P = I xi + dt/2 xi x I xi + dt^2/4 (xi . I xi) xi        (dcay^-1 transposed, applied to I xi)
// solved by Newton's method; the momentum at the end, I xi - dt/2 xi x I xi + dt^2/4 (.) xi,
// is then L^{n+1/2} seen from q^{n+1}. Torque enters by the kicks around it.
#include "schemes/kick_drift_kick.hpp"

#include <Eigen/LU>

namespace rotbench {
namespace {

template <class S>
Eigen::Matrix<S, 3, 3> hat(const Vec3T<S>& v) {
    Eigen::Matrix<S, 3, 3> m;
    m << S(0.0), -v.z(), v.y(), v.z(), S(0.0), -v.x(), -v.y(), v.x(), S(0.0);
    return m;
}

struct CayleyRotation {
    template <class S>
    static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, double dt) {
        using Matrix3 = Eigen::Matrix<S, 3, 3>;
        const Vec3T<S>& inertia = start.inertia;
        const Vec3T<S> p = to_body(start.q, momentum);
        Vec3T<S> xi = p.cwiseQuotient(inertia);
        constexpr int max_iterations = 50;
        auto iterating = all_true<S>();  // in a pack each body stops at its own iteration, as alone
        for (int i = 0;; ++i) {
            const Vec3T<S> ixi = inertia.cwiseProduct(xi);
            const S s = xi.dot(ixi);
            const Vec3T<S> residual = ixi + 0.5 * dt * xi.cross(ixi) + 0.25 * dt * dt * s * xi - p;
            const Matrix3 jacobian = Matrix3(inertia.asDiagonal()) + 0.5 * dt * (hat(xi) * inertia.asDiagonal() - hat(ixi)) +
                                     0.25 * dt * dt * (s * Matrix3::Identity() + 2.0 * xi * ixi.transpose());
            // The closed-form 3x3 inverse (cofactors): half the cost of a pivoted LU here.
            // The Jacobian is I + O(dt |xi|), far from singular wherever Newton converges.
            const Vec3T<S> delta = jacobian.inverse() * residual;
            xi = select(iterating, Vec3T<S>(xi - delta), xi);
            // Newton converges quadratically: stop at a few units of round-off.
            const S step = delta.norm();
            iterating = iterating && !(step <= 1e-15 * xi.norm() || !is_finite(step));
            if (!any_lane(iterating)) break;
            if (i == max_iterations)
                throw std::runtime_error("cayley: Newton's method did not converge in 50 iterations (time step too large)");
        }
        return start.q * cayley_rotation<S>(dt * xi);
    }
};

const RegisterScheme<KickDriftKick<CayleyRotation>> registration(
    "cayley", "Cayley-map Lie-group variational integrator (implicit, Newton)",
    "Li et al., Comp. Part. Mech. (2024); Lee, Leok & McClamroch, Comput. Methods Appl. Mech. Eng. 196:2907 (2007)",
    "Our reading: kick of L with T^n; discrete Euler-Poincare step q^{n+1} = q^n cay(dt xi) with "
    "P = I xi + dt/2 xi x I xi + dt^2/4 (xi.I xi) xi for the body momentum P at q^n, solved by Newton's method; kick "
    "with T^{n+1}. Symplectic and time-reversible; |q| = 1 kept. A step where Newton fails is a failed run.",
    kick_drift_kick_claims({.order = {2, "a variational integrator with a symmetric discrete Lagrangian: second order"},
                            .symmetric = true}));

}  // namespace
}  // namespace rotbench
