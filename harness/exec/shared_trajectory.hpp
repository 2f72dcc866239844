// Reference trajectories shared by the runs of one process. Every scheme of a sweep is
// compared with the same reference at the same steps, so a trajectory is computed once per
// key (scene, parameters, dt, steps) and handed to every run that asks for it; a run that
// asks while another is computing it waits for that one instead of repeating the work. A
// failure is shared too, unless it came from an interrupt or memory running out.
#pragma once

#include "references/trajectory.hpp"

#include <functional>
#include <memory>
#include <string>

namespace rotbench {

std::shared_ptr<const Trajectory> shared_trajectory(const std::string& key, const std::function<Trajectory()>& compute);

}  // namespace rotbench
