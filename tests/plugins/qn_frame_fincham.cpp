// Test plug-in: the Fincham leapfrog of a widely used DEM engine's current Debian release
// (Yade 2023.02a, leapfrogAsphericalRotate), which takes the half-step body velocity in the
// frame of q^n instead of q^{n+1/2}. With that one frame changed it is rotbench's `fincham`;
// as it is, it is first order. It registers fincham's claims; the default gate must fail it.
#include "schemes/kick_drift_kick.hpp"

namespace {

using namespace rotbench;

struct QnFrameFinchamRotation {
    static Quat rotate(const RigidBody& start, const Vec3& momentum, double dt) {
        const Quat& q = start.q;
        const Quat half(q.coeffs() + 0.5 * dt * quaternion_rate(q, start.omega));
        const Vec3 omega_half = omega_from_momentum(q, start.inertia, momentum);  // frame of q^n, not of the half step
        return Quat(q.coeffs() + dt * quaternion_rate(half, omega_half)).normalized();
    }
};

const RegisterScheme<KickDriftKick<QnFrameFinchamRotation>> registration(
    "fincham_qn_frame", "test plug-in: Fincham's leapfrog with the half-step velocity in the frame of q^n (claims fincham's)",
    "tests/plugins", "",
    {.without_torque = {2, "as fincham (claimed, not delivered)"},
     .with_torque = {2, "as fincham"},
     .conserves_momentum = true});

}  // namespace
