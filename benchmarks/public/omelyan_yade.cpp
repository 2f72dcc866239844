// `omelyan__yade`: Omelyan's step as Yade's NewtonIntegrator takes it for an aspherical body
// (leapfrogAsphericalRotateOmelyan_1998), written anew for the cost table's side-by-side
// comparison with rotbench's `omelyan`. Yade's reading is a leapfrog in the body frame: the
// mid-step w' solved from Euler's equations by a fixed three passes (niterOmelyan1998), the
// Cayley-type quaternion update with it, w and L taken back through the rotation matrix of
// q^n, and q normalised every 5000 steps. The force model therefore sees w at the half step.
// Another map than `omelyan` (whose mid-point iteration runs on q to round-off): it claims
// nothing, and only its cost is compared.
#include "benchmarks/public/yade_math.hpp"

namespace rotbench {
namespace {

using namespace yade_style;

struct OmelyanYade {
    static constexpr int iterations = 3;  // Yade's niterOmelyan1998 default

    using Memory = LeapfrogMemory;

    static void start(const RigidBody&, Memory&) {}  // a fresh memory counts from step 0

    static void predict(RigidBody& b, Memory& m, double dt) {
        const Eigen::Matrix3d A = b.q.conjugate().toRotationMatrix();  // global to local
        const Vec3 w = A * b.omega;
        const Vec3 I = b.inertia, tau = A * b.torque;
        Vec3 ww = w;
        for (int i = 0; i < iterations; ++i)
            ww = w + (tau + 0.5 * Vec3((w[1] * w[2] + ww[1] * ww[2]) * (I[1] - I[2]), (w[2] * w[0] + ww[2] * ww[0]) * (I[2] - I[0]),
                                       (w[0] * w[1] + ww[0] * ww[1]) * (I[0] - I[1])))
                             .cwiseQuotient(I) *
                         dt;
        const double a = dt * dt * ww.squaredNorm() * 0.0625;
        if (a != 0.0) b.q = Quat(((1.0 - a) / (1.0 + a)) * b.q.coeffs() + (dt / (1.0 + a)) * rate(ww, b.q).coeffs());
        finish_leapfrog(b, m, A, ww);
    }

    static void correct(RigidBody&, Memory&, double) {}  // the torque of the step entered in predict
};

const RegisterScheme<OmelyanYade> registration(
    "omelyan__yade", "public-code counterpart: Omelyan's step as in Yade's NewtonIntegrator (Omelyan1998)",
    "Yade pkg/dem/NewtonIntegrator.cpp leapfrogAsphericalRotateOmelyan_1998, read and written anew",
    "Leapfrog in the body frame: w' at the half step from three fixed-point passes of Euler's equations with T^n; "
    "q^{n+1} = [(1 - a) q + dt dq/dt(w')]/(1 + a), a = dt^2 |w'|^2/16; L and w through the matrix of q^n; q normalised "
    "every 5000 steps. For the cost table only: it claims nothing.");

}  // namespace
}  // namespace rotbench
