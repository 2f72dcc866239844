// Trajectory exports (docs/cli.md), one body, columns
//   t,qw,qx,qy,qz,wx,wy,wz,wbx,wby,wbz,x,y,z,vx,vy,vz,energy
// (w: world angular velocity, wb: body frame). A scheme's export is a run of kind states
// (harness/exec/run_kinds.hpp), made by the executor like any other run.
#pragma once

#include "harness/scenes/scene.hpp"

#include <string>
#include <vector>

namespace rotbench {

inline constexpr const char* trajectory_header = "t,qw,qx,qy,qz,wx,wy,wz,wbx,wby,wbz,x,y,z,vx,vy,vz,energy";

// The scene's reference at `samples` + 1 equally spaced times over [0, t_end]: its closed
// form where it has one (those scenes are force-free: x = x0 + v0 t), otherwise Odeint.
std::vector<std::vector<double>> reference_states(const Scene& scene, int samples);

// One row of the export from the state of body 0 in `b` (its energy: the scene's total).
std::vector<double> state_row(const Scene& scene, double t, const Bodies& b);

}  // namespace rotbench
