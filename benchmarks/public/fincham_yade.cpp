// `fincham__yade`: Fincham's rotational leapfrog as Yade's NewtonIntegrator steps an
// aspherical body (leapfrogAsphericalRotate: Eigen quaternions and one rotation matrix, that
// of q^n, for both body-frame angular velocities; the half-step quaternion left unnormalised),
// in its synchronous form, written anew for the cost table's side-by-side comparison with
// rotbench's `fincham`. Taking the half step's w' in the frame of q^n is Yade's own reading
// of Fincham's rule, not the textbook one: the errors differ from `fincham`'s, so it claims
// no order; only its cost is compared.
#include "benchmarks/public/yade_math.hpp"

namespace rotbench {
namespace {

using yade_style::rate;

struct FinchamYade {
    struct Memory {
        Vec3 angmom;  // world
    };

    static void start(const RigidBody& b, Memory& m) {
        m.angmom = b.q * b.inertia.cwiseProduct(b.q.conjugate() * b.omega);
    }

    static void predict(RigidBody& b, Memory& m, double dt) {
        const Eigen::Matrix3d to_body = b.q.conjugate().toRotationMatrix();  // of q^n
        const Vec3 omega_body_n = (to_body * m.angmom).cwiseQuotient(b.inertia);
        const Quat q_half(b.q.coeffs() + 0.5 * dt * rate(omega_body_n, b.q).coeffs());
        m.angmom += 0.5 * dt * b.torque;
        const Vec3 omega_body_half = (to_body * m.angmom).cwiseQuotient(b.inertia);
        b.q = Quat(b.q.coeffs() + dt * rate(omega_body_half, q_half).coeffs());
        b.q.normalize();
        b.omega = b.q * omega_body_half;  // Yade's angVel: w at the half step
    }

    static void correct(RigidBody& b, Memory& m, double dt) {
        m.angmom += 0.5 * dt * b.torque;
        b.omega = b.q * (b.q.conjugate() * m.angmom).cwiseQuotient(b.inertia);
    }
};

const RegisterScheme<FinchamYade> registration(
    "fincham__yade", "public-code counterpart: Fincham's leapfrog as in Yade's NewtonIntegrator",
    "Yade pkg/dem/NewtonIntegrator.cpp leapfrogAsphericalRotate, read and written anew (synchronous form)",
    "w' at q^n from L^n; q_half = q + dt/2 dq/dt (not normalised); kick of L; w' from L^{n+1/2} in the frame of q^n; "
    "q + dt dq/dt(w', q_half); normalise; kick. For the cost table only: it claims nothing.");

}  // namespace
}  // namespace rotbench
