// What the two public codes' NO_SQUISH counterparts (LAMMPS's MathExtra::no_squish_rotate,
// HOOMD-blue's TwoStepNVE) share: the permutations of Miller et al. and what they claim.
#pragma once

#include "schemes/scheme.hpp"

namespace rotbench::public_codes {

// P_k q of Miller et al., J. Chem. Phys. 116:8649 (2002), eq. 2.11, about which every free
// rotor turns (k = 1, 2, 3: the body axes; q as w, x, y, z).

inline void permute(int k, const double q[4], double out[4]) {
    if (k == 1) out[0] = -q[1], out[1] = q[0], out[2] = q[3], out[3] = -q[2];
    else if (k == 2) out[0] = -q[2], out[1] = -q[3], out[2] = q[0], out[3] = q[1];
    else out[0] = -q[3], out[1] = q[2], out[2] = -q[1], out[3] = q[0];
}

// Both compute no_squish's map in exact arithmetic, so they claim what it claims.
inline SchemeClaims no_squish_claims() {
    return {.without_torque = {2, "the same map as no_squish"},
            .with_torque = {2, "the same map as no_squish"},
            .conserves_momentum = true,
            .bounded_energy = true,
            .time_reversible = true};
}

}  // namespace rotbench::public_codes
