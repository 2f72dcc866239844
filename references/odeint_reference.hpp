// The Boost.Odeint reference engine: integrates any scene's equations of motion
//     x' = v,  v' = F/m,  q' = (0, w) q / 2 with w = I(q)^-1 L,  L' = T
// (world frame, one state block per body), with the scene's own force/torque model. It
// lands exactly on the sample times and on every change of sign of a contact gap.
#pragma once

#include "references/trajectory.hpp"

#include <functional>
#include <vector>

namespace rotbench {

enum class OdeMethod {
    fehlberg78,      // runge_kutta_fehlberg78 with make_controlled: the reference
    bulirsch_stoer,  // the cross-check
};

// Tolerance of the reference (absolute and relative, per state component). 1e-13 leaves
// the fibre's energy error at 1e-9; 1e-14 brings it to 5e-10 and below.
inline constexpr double reference_tolerance = 1e-14;

// t_k = t_end k / samples, k = 0 .. samples.
std::vector<double> equally_spaced_times(double t_end, int samples);

// `keep_going`, when given, is asked every thousand steps; once it says no, the integration
// throws (an interrupted sweep does not wait for a long reference to finish).
Trajectory integrate_scene(const Dynamics& scene, const std::vector<double>& times, OdeMethod method,
                           double tolerance = reference_tolerance, const std::function<bool()>& keep_going = {});

// Largest difference between the two methods on `samples` + 1 equally spaced times over
// [0, t_end]: angular velocity relative to its largest norm, orientation angle (rad),
// position relative to the largest |x| (or absolute when the bodies stay at the origin).
struct CrossCheck {
    double omega_relative = 0, angle = 0, position = 0;
};
CrossCheck cross_check(const Dynamics& scene, double t_end, int samples = 200, double tolerance = reference_tolerance);

}  // namespace rotbench
