#include "harness/exec/run_kinds.hpp"

#include <fmt/format.h>

namespace rotbench {

// Two trajectory runs, over the scene's duration and energy_horizon times it: the longer one's
// first stretch is the shorter one bit for bit, so this is one run read at two times.
RunResult run_horizon(const RunSpec& requested, const SchemeFactory& make) {
    RunSpec first = requested;
    first.kind = RunKind::trajectory;
    first.timed = false;
    first.t_end = scene_of(requested)->t_end();
    RunSpec longer = first;
    longer.t_end = energy_horizon * first.t_end;
    RunResult result{requested, {}, {}};
    result.spec.t_end = first.t_end;
    for (const auto& [spec, name] : {std::pair{first, metric::energy_drift_first}, std::pair{longer, metric::energy_drift_horizon}}) {
        const RunResult r = run_trajectory(spec, {.measure_time = false}, make);
        if (r.interrupted) {
            result.interrupted = true;
            return result;
        }
        if (!r.failure.empty()) {
            result.failure = fmt::format("over {:g} s: {}", spec.t_end, r.failure);
            result.metrics.clear();
            return result;
        }
        result.metrics.emplace_back(name, r.value(metric::energy_drift_max));
    }
    return result;
}

}  // namespace rotbench
