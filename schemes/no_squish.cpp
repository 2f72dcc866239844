// `no_squish`: the symplectic splitting of Miller, Eleftheriou, Pattnaik, Ndirango, Newns &
// Martyna, J. Chem. Phys. 116:8649 (2002), as in LAMMPS (fix rigid/nve, fix nve/asphere) and
// HOOMD. LAMMPS's fix rigid/nve is this map when the principal moments come in descending order;
// it labels the axes itself, and the order of the sub-steps depends on the labels (docs/clients.md).
//
// The free-rotor Hamiltonian is split by principal axis, H = sum_k L'_k^2 / (2 I_k), and
// each piece is flowed exactly: under H_k the body turns about its own axis k by
// phi = t L'_k / I_k, and the body components of L turn by -phi about the same axis. The
// symmetric sequence k = 3, 2, 1, 2, 3 with steps dt/2, dt/2, dt, dt/2, dt/2 (Miller et al.
// eq. 21) is second order and time-reversible. Miller et al. write each piece with the
// conjugate quaternion momentum p = 2 S(q) (0, L') and the permutations P_k:
// q <- cos(z) q + sin(z) P_k q with z = dt p.P_k q / (4 I_k) = dt L'_k / (2 I_k); that is the
// same rotation by phi = 2 z written in the body momentum, which is what is done here.
#include "schemes/kick_drift_kick.hpp"

namespace rotbench {
namespace {

struct NoSquishRotation {
    // The exact flow of H_k for a time t: the turn by phi about body axis k is the exponential
    // map of the shared helpers (schemes/quaternion.hpp: series below a radian, so a pack gets
    // the bits of the bodies alone), (cos(phi/2), sin(phi/2) e_k); the body momentum turns by
    // -phi, with cos(phi) and sin(phi) from the half angle by the double-angle formulas.
    // k is a template argument so that every index below is known when compiled: a pack's
    // components then stay in registers (with k a variable they went through memory).
    template <int k, class S>
    ROTBENCH_INLINE static void rotate_about_axis(double t, QuatT<S>& q, Vec3T<S>& momentum_body, const Vec3T<S>& inertia) {
        Vec3T<S> theta = Vec3T<S>::Zero();
        theta[k] = t * momentum_body[k] / inertia[k];
        const QuatT<S> turn = rotation_from_vector<S>(theta);
        const S half_cos = turn.w(), half_sin = turn.vec()[k];
        const S c = half_cos * half_cos - half_sin * half_sin, s = 2.0 * half_cos * half_sin;
        constexpr int i = (k + 1) % 3, j = (k + 2) % 3;
        const S li = momentum_body[i], lj = momentum_body[j];
        momentum_body[i] = c * li + s * lj;  // the fixed vector L seen from the turned body
        momentum_body[j] = -s * li + c * lj;
        q = q * turn;
    }

    template <class S>
    static QuatT<S> rotate(const RigidBodyT<S>& start, const Vec3T<S>& momentum, double dt) {
        QuatT<S> q = start.q;
        Vec3T<S> l = to_body(q, momentum);
        rotate_about_axis<2, S>(0.5 * dt, q, l, start.inertia);
        rotate_about_axis<1, S>(0.5 * dt, q, l, start.inertia);
        rotate_about_axis<0, S>(dt, q, l, start.inertia);
        rotate_about_axis<1, S>(0.5 * dt, q, l, start.inertia);
        rotate_about_axis<2, S>(0.5 * dt, q, l, start.inertia);
        return q;
    }
};

const RegisterScheme<KickDriftKick<NoSquishRotation>> registration(
    "no_squish", "NO_SQUISH symplectic splitting by principal axis (LAMMPS rigid/nve, HOOMD)",
    "Miller et al., J. Chem. Phys. 116:8649 (2002), eqs. 19-21",
    "Kick of L with T^n, exact rotations about the body axes 3, 2, 1, 2, 3 with steps dt/2, dt/2, dt, dt/2, dt/2, "
    "kick with T^{n+1}. Each axis rotation is written with the body angular momentum rather than Miller's quaternion "
    "momentum p; the two are the same map. Symplectic and time-reversible: no energy drift, |q| = 1 kept.",
    kick_drift_kick_claims({.order = {2, "a symmetric composition of exact flows (Strang splitting): second order"},
                            .symmetric = true}));

}  // namespace
}  // namespace rotbench
