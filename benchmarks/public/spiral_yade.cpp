// `spiral__yade`: SPIRAL as Yade's NewtonIntegrator steps an aspherical body (its default,
// leapfrogAsphericalRotateCarlos_2023), written anew for the cost table's side-by-side
// comparison with rotbench's `spiral`. Yade's reading is a leapfrog: w' advanced by SSPRK3 on
// Euler's equations with T^n, then one rotation q^{n+1} = q^n exp(dt/2 w') with the new w'
// (libm's sin and cos), w and L taken back through the rotation matrix of q^n, q normalised
// every 5000 steps. The force model sees w at the half step. Another map than `spiral`
// (the synchronous form with two exponentials): it claims nothing, and only its cost is
// compared.
#include "benchmarks/public/yade_math.hpp"

#include <cmath>

namespace rotbench {
namespace {

using namespace yade_style;

// I' dw'/dt = T' - w' x I' w', component by component as Yade's w_dot divides.
Vec3 w_dot(const Vec3& w, const Vec3& M, const Vec3& I) {
    return {(M[0] + w[1] * w[2] * (I[1] - I[2])) / I[0], (M[1] + w[2] * w[0] * (I[2] - I[0])) / I[1],
            (M[2] + w[0] * w[1] * (I[0] - I[1])) / I[2]};
}

struct SpiralYade {
    using Memory = LeapfrogMemory;

    static void start(const RigidBody&, Memory&) {}  // a fresh memory counts from step 0

    static void predict(RigidBody& b, Memory& m, double dt) {
        const Eigen::Matrix3d A = b.q.conjugate().toRotationMatrix();  // global to local
        Vec3 w = A * b.omega;
        const Vec3 tau = A * b.torque;
        const Vec3 k1 = dt * w_dot(w, tau, b.inertia);
        const Vec3 k2 = dt * w_dot(w + k1, tau, b.inertia);
        const Vec3 k3 = dt * w_dot(w + 0.25 * (k1 + k2), tau, b.inertia);
        w += (k1 + k2 + 4.0 * k3) / 6.0;
        double norm = w.squaredNorm();
        if (norm != 0.0) {
            norm = std::sqrt(norm);
            const double theta = dt * norm * 0.5;
            b.q = b.q * Quat(std::cos(theta), std::sin(theta) * w[0] / norm, std::sin(theta) * w[1] / norm,
                             std::sin(theta) * w[2] / norm);
        }
        finish_leapfrog(b, m, A, w);
    }

    static void correct(RigidBody&, Memory&, double) {}  // the torque of the step entered in predict
};

const RegisterScheme<SpiralYade> registration(
    "spiral__yade", "public-code counterpart: SPIRAL as in Yade's NewtonIntegrator (delValle2023, its default)",
    "Yade pkg/dem/NewtonIntegrator.cpp leapfrogAsphericalRotateCarlos_2023, read and written anew",
    "Leapfrog in the body frame: w' advanced by SSPRK3 on Euler's equations with T^n, then q^{n+1} = q^n exp(dt/2 w') "
    "with the new w' (libm's sin and cos); L and w through the matrix of q^n; q normalised every 5000 steps. For the "
    "cost table only: it claims nothing.");

}  // namespace
}  // namespace rotbench
