// A client's run (harness/store/client.hpp): rotbench writes the scene as data (scene.json) in a
// scratch directory of its own, starts the client's program there with `scene.json
// trajectory.csv` after its arguments, under the run limits of an isolated worker, reads back the
// trajectory it wrote, and judges it exactly like a built-in run: the trajectory is replayed
// step by step through the same loop, the same metrics against the same reference. The scratch
// directory, with whatever the program left in it, is removed afterwards. docs/clients.md.
#pragma once

#include "harness/exec/client_trajectory.hpp"
#include "harness/exec/isolation.hpp"
#include "harness/exec/run.hpp"

#include <string>

namespace rotbench {

// The exit status with which a client's program says "this scene or these parameters are not
// mine" (docs/clients.md): the run is skipped with the last line of its standard error, not failed.
inline constexpr int client_declines = 3;

// The scene's spec as a client reads it, for a run of `steps` steps of `dt` (t_end = steps dt,
// to within round-off): a granular scene's, a contact scene's, or one body's. InputError when
// the scene is none of these (one body not under a TorqueLaw).
std::string client_scene_json(const Scene& scene, const RunSpec& spec, double t_end, std::int64_t steps);

// Runs of kind trajectory and horizon (on a granular scene, trajectory only: the program runs the
// scene itself and writes samples of its stones, harness/exec/granular_client.hpp; on a contact
// scene, also stability: a built-in's search, each trial one run of the program,
// harness/exec/contact_client.hpp); any other kind, a scene the client file does not list, a
// program that fails, hangs or writes a trajectory that is malformed, short, or (but on a contact
// scene, where that is a blow-up) not finite is a failed run saying which; one that exits
// with client_declines declined it. The built-ins' timing metrics are not measured: every run
// records its program's own CPU and wall time instead.
RunResult run_client(const RunSpec& spec, const RunOptions& options, const IsolationLimits& limits);

}  // namespace rotbench
