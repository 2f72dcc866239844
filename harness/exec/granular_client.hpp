// A client's run on a granular scene (silo_discharge): the DEM code runs the whole scene itself
// from a description of it, and rotbench reads back the stones at sample times and hands them
// to the scene's own probe, so its metrics are computed exactly as a built-in run's
// (docs/clients.md, "Granular scenes").
#pragma once

#include "harness/exec/run.hpp"
#include "harness/scenes/granular_scene.hpp"

#include <cstdint>
#include <filesystem>
#include <string>

namespace rotbench {

// The columns of a granular client's samples: time, the stone (0 ... count - 1, the client's
// own numbering, the same in every sample), its shape (index into the spec's shapes), the
// position of its centre of mass, its orientation (body = the shape's principal frame, to
// world, w first), its velocity and its world angular velocity.
inline constexpr const char* granular_samples_header = "t,stone,shape,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz";
// Between samples: 10 ms, the resolution of the mass curve a client is judged on.
inline constexpr double granular_sample_interval = 0.01;

// The steps a granular client writes samples at: every multiple of `stride` from `first` (the
// first at or after the time the scene's probe looks from) to the run's last step.
struct SampleSteps {
    std::int64_t first = 0, stride = 1;
};
SampleSteps granular_sample_steps(const GranularScene& scene, double dt);

// The scene's spec as a granular client reads it. InputError when its walls move (nullopt
// wall_changes()).
std::string granular_scene_json(const GranularScene& scene, const RunSpec& spec, double t_end, std::int64_t steps);

// The run judged from the client's samples: each sample, as the stones stand, to the scene's
// probe. A missing, malformed, short or non-finite samples file is a failed run saying why.
RunResult replay_granular_samples(const RunSpec& spec, GranularScene& scene, const std::filesystem::path& samples, std::int64_t steps);

}  // namespace rotbench
