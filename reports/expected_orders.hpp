// The order each seed scheme should show, and why (tests check the observed orders
// against these; the report prints them beside the observed ones). The orders are of the
// angular-velocity error, omega_err_max.
#pragma once

#include <string>
#include <vector>

namespace rotbench {

struct ExpectedOrder {
    std::string scheme;
    bool with_torque;  // false: torque-free scenes; true: an orientation-dependent torque
    int order;
    std::string reason;
};

inline const std::vector<ExpectedOrder>& expected_orders() {
    static const std::vector<ExpectedOrder> table = {
        {"direct", false, 1,
         "eq. 41 takes the gyroscopic term at w^{n+1/2} and the corrector in the frame of q^n (the readings that "
         "reproduce Table 1): an O(dt) error in the end-of-step acceleration, so first order"},
        {"direct", true, 1, "as without torque; the torque itself is averaged over the step (eqs. 36, 43)"},
        {"munjiza_rk4", false, 2,
         "H is exact without torque; the RK average of w followed by one exponential map (eqs. 50-51) misses "
         "the commutator of the rotations within the step: second order, not fourth"},
        {"munjiza_rk4", true, 1, "eq. 44 advances H with the start-of-step torque only (explicit Euler): first order"},
        {"zvw", false, 2, "without torque, w' follows the explicit mid-point rule (eqs. 56-57, 63): second order"},
        {"zvw", true, 1, "the velocity update uses the start-of-step torque only: first order"},
        {"zvw_corrected", false, 2, "identical to zvw without torque"},
        {"zvw_corrected", true, 1, "the velocity update uses the end-of-step torque only (eq. 63): first order"},
    };
    return table;
}

}  // namespace rotbench
