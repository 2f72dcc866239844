// A sweep's plan: every selected scheme on every selected scene at every time step, and the
// runs the claims need beside them.
#pragma once

#include "harness/core/run.hpp"

#include <map>
#include <string>
#include <vector>

namespace rotbench {

struct SweepSpec {
    std::vector<std::string> scenes;               // empty: every registered scene
    std::vector<std::string> schemes;              // empty: every registered scheme
    std::vector<double> dts;                       // empty: each scene's default ladder
    double t_end = 0.0;                            // 0: each scene's default
    bool quick = false;                            // each scene's quick ladder and sizes instead of its default ones
    int ensemble = 1;                              // runs per scheme and dt of a scene with a `seed` key, seeds seed ... seed + K - 1
    std::map<std::string, ParamOverrides> params;  // scene id -> overrides (--set, config)
};

// The runs of a sweep in a fixed order (scene, scheme, dt as given, then ensemble member; then,
// on a scene where bounded energy is judged, the scheme's horizon run at the coarsest dt,
// harness/analysis/claims.hpp). Checks every input first, so a bad one is reported before
// anything runs (InputError).
// A client scheme is planned only on the scenes its file lists; each pair skipped is said in
// `skipped`, when given.
std::vector<RunSpec> plan_sweep(const SweepSpec& spec, std::vector<std::string>* skipped = nullptr);

}  // namespace rotbench
