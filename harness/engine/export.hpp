// Trajectory exports (docs/cli.md), one body, columns
//   t,qw,qx,qy,qz,wx,wy,wz,wbx,wby,wbz,x,y,z,vx,vy,vz,energy
// (w: world angular velocity, wb: body frame).
#pragma once

#include "harness/scenes/scene.hpp"

#include <string>

namespace rotbench {

inline constexpr const char* trajectory_header = "t,qw,qx,qy,qz,wx,wy,wz,wbx,wby,wbz,x,y,z,vx,vy,vz,energy";

// The scene's reference at `samples` + 1 equally spaced times over [0, t_end]: its closed
// form where it has one (those scenes are force-free: x = x0 + v0 t), otherwise Odeint.
std::string reference_csv(const Scene& scene, int samples);

// A scheme's run at step dt, every step, or every k-th step so that at most `samples` + 1
// rows are written. A run that blows up or throws ends at its last finite step; why it
// stopped goes to *stopped (empty when it did not).
std::string scheme_trajectory_csv(const Scene& scene, const std::string& scheme_id, double dt, int samples,
                                  std::string* stopped = nullptr);

}  // namespace rotbench
