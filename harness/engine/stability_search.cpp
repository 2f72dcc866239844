#include "harness/analysis/stability.hpp"
#include "harness/engine/interrupt.hpp"
#include "harness/engine/run_kinds.hpp"

namespace rotbench {

RunResult run_stability_search(const RunSpec& requested) {
    SchemeRegistry::instance().at(requested.scheme, "scheme");
    const auto scene = scene_of(requested);
    const auto* probe = dynamic_cast<const StabilityProbe*>(scene.get());
    if (!probe) throw InputError("scene '" + requested.scene + "' is not a stability scene");
    RunResult result{requested, {}, {}};
    result.spec.t_end = scene->t_end();
    const StabilityCriterion criterion = stability_criterion(*probe);
    const double limit = empirical_limit(*scene, requested.scheme, probe->predicted_limit(), criterion);
    if (interrupt_signal()) {
        result.interrupted = true;
        return result;
    }
    result.metrics = {{metric::dt_empirical, limit},
                      {metric::dt_peng, probe->predicted_limit()},
                      {metric::stability_ratio, limit / probe->predicted_limit()}};
    return result;
}

}  // namespace rotbench
