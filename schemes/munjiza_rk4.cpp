#include "schemes/munjiza_rk4.hpp"

namespace rotbench {
namespace {

const RegisterScheme<MunjizaRk4<>> registration(
    "munjiza_rk4", "Munjiza's Runge-Kutta averaged angular velocity, quaternion form",
    "Irazabal et al., seed 000, eqs. 44-53 (after Munjiza et al.)",
    "H is advanced with the start-of-step torque T^n (eq. 44), so the whole step is done "
    "before the force evaluation; the force model sees w^{n+1}. No choice was left open.",
    {.without_torque = {2, "H is exact without torque; the RK average of w followed by one exponential map (eqs. "
                           "50-51) misses the commutator of the rotations within the step: second order, not fourth"},
     .with_torque = {1, "eq. 44 advances H with the start-of-step torque only (explicit Euler): first order"},
     .conserves_momentum = true,
     .family = "seed"});

}  // namespace
}  // namespace rotbench
