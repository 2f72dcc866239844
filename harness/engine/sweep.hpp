// A sweep: every selected scheme on every selected scene at every time step.
#pragma once

#include "harness/engine/run.hpp"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace rotbench {

struct SweepSpec {
    std::vector<std::string> scenes;   // empty: every registered scene
    std::vector<std::string> schemes;  // empty: every registered scheme
    std::vector<double> dts;           // empty: each scene's default ladder
    double t_end = 0.0;                // 0: each scene's default
    bool quick = false;                // each scene's quick ladder and sizes instead of its default ones
    int ensemble = 1;                  // runs per scheme and dt of a scene with a `seed` key, seeds seed ... seed + K - 1
    std::map<std::string, ParamOverrides> params;  // scene id -> overrides (--set, config)
};

// The runs of a sweep in a fixed order (scene, scheme, dt as given, then ensemble member; then,
// on a scene where bounded energy is judged, the scheme's horizon run at the coarsest dt,
// harness/analysis/claims.hpp). Checks every input first, so a bad one is reported before
// anything runs (InputError).
std::vector<RunSpec> plan_sweep(const SweepSpec& spec);

// Runs the plan on `jobs` threads; a failing run is recorded and the sweep goes on. The
// results come back in plan order whatever `jobs` is, and are the same bit for bit apart
// from the timing metrics. `on_done(i, result)` is called after run i, one call at a time,
// in the order the runs finish. Once SIGINT or SIGTERM is caught (harness/interrupt.hpp) no
// run starts, the runs in flight stop, and on_done is not called for them. `on_start(i)` is
// called as run i starts, from the thread that runs it.
std::vector<RunResult> run_sweep(const std::vector<RunSpec>& plan, const RunOptions& options = {},
                                 const std::function<void(std::size_t, const RunResult&)>& on_done = {}, int jobs = 1,
                                 const std::function<void(std::size_t)>& on_start = {});

}  // namespace rotbench
