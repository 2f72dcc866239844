#include "schemes/munjiza_rk4.hpp"

namespace rotbench {
namespace {

const RegisterScheme<MunjizaRk4<>> registration(
    "munjiza_rk4", "Munjiza's Runge-Kutta averaged angular velocity, quaternion form",
    "Irazabal et al., seed 000, eqs. 44-53 (after Munjiza et al.)",
    "H is advanced with the start-of-step torque T^n (eq. 44), so the whole step is done "
    "before the force evaluation; the force model sees w^{n+1}. No choice was left open.");

}  // namespace
}  // namespace rotbench
