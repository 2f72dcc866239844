// Closed-form critical time steps of Peng, Burns & Hanley (seed 004) for two convex,
// centrally symmetric particles in one linear spring-dashpot contact. These are
// predictions to be tested (harness/stability.hpp measures the real limits).
#pragma once

#include "schemes/bodies.hpp"

#include <algorithm>
#include <cmath>

namespace rotbench::peng {

// Seed 004 eq. 26: A_max = a1^2/I_xx1 + a2^2/I_xx2 + 1/m1 + 1/m2, with a the largest
// semi-axis and I_xx the smallest principal moment of each particle.
inline double a_max(double a1, double i_min1, double m1, double a2, double i_min2, double m2) {
    return a1 * a1 / i_min1 + a2 * a2 / i_min2 + 1.0 / m1 + 1.0 / m2;
}

// Eq. 46 (amplification matrix of the Euler integrator, any damping c >= 0):
// dt = (sqrt(4 k A + c^2 A^2) + c A) / (k A).
inline double damped(double k, double c, double a) {
    return (std::sqrt(4.0 * k * a + c * c * a * a) + c * a) / (k * a);
}

// Eqs. 47-48: the undamped case, dt = 2 / sqrt(k A).
inline double undamped(double k, double a) { return 2.0 / std::sqrt(k * a); }

// Eq. 37: the critical damping coefficient of the contact mode, 2 sqrt(k / A).
inline double critical_damping(double k, double a) { return 2.0 * std::sqrt(k / a); }

// Eq. 54: B_max = max(|Ixx - Iyy|/Izz, |Ixx - Izz|/Iyy, |Iyy - Izz|/Ixx).
inline double b_max(const Vec3& i) {
    return std::max({std::abs(i.x() - i.y()) / i.z(), std::abs(i.x() - i.z()) / i.y(), std::abs(i.y() - i.z()) / i.x()});
}

// Eq. 57: the rotation-dominant critical time step, 1 / (w_max B_max).
inline double rotation_dominant(double omega_max, double bmax) { return 1.0 / (omega_max * bmax); }

// The textbook limit of the integrator the translation uses (Velocity Verlet, or
// central differences): dt < 2 / w for an undamped oscillator of angular frequency w.
inline double verlet_limit(double omega) { return 2.0 / omega; }

}  // namespace rotbench::peng
