// The runs of kind stability, amplification and spectral (harness/exec/run_kinds.hpp).
#include "harness/exec/interrupt.hpp"
#include "harness/exec/run_kinds.hpp"
#include "harness/exec/stability.hpp"

#include <cmath>
#include <limits>

namespace rotbench {
namespace {

// The run's scene, which must have a stability probe, and its result with the scene's duration.
struct StabilityRun {
    std::unique_ptr<Scene> scene;
    const StabilityProbe* probe;
    RunResult result;
};
StabilityRun stability_run(const RunSpec& requested, bool linearised) {
    SchemeRegistry::instance().at(requested.scheme, "scheme");
    auto scene = scene_of(requested);
    const auto* probe = dynamic_cast<const StabilityProbe*>(scene.get());
    if (!probe) throw InputError("scene '" + requested.scene + "' is not a stability scene");
    if (linearised && !probe->linearisable_at_rest())
        throw InputError("scene '" + requested.scene + "' cannot be linearised at rest: it has no " + kind_name(requested.kind));
    RunResult result{requested, {}, {}};
    result.spec.t_end = scene->t_end();
    return {std::move(scene), probe, std::move(result)};
}

RunResult unless_interrupted(RunResult result) {
    if (interrupt_signal()) result = {result.spec, {}, {}, true};
    return result;
}

}  // namespace

RunResult run_stability_search(const RunSpec& requested) {
    auto [scene, probe, result] = stability_run(requested, false);
    const double peng = probe->predicted_limit();
    const double limit = empirical_limit(*scene, requested.scheme, peng, stability_criterion(*probe));
    result.metrics = {{metric::dt_empirical, limit}, {metric::dt_peng, peng}, {metric::stability_ratio, limit / peng}};
    return unless_interrupted(std::move(result));
}

RunResult run_amplification(const RunSpec& requested) {
    auto [scene, probe, result] = stability_run(requested, true);
    const double peng = probe->predicted_limit();
    const double limit = amplification_limit(*scene, requested.scheme, peng, stability_criterion(*probe));
    const bool weak = unstable_at_every_dt(*scene, requested.scheme, 0.01 * peng);
    result.metrics = {{metric::dt_amplification, limit}, {metric::unstable_at_every_dt, weak ? 1.0 : 0.0}};
    return unless_interrupted(std::move(result));
}

RunResult run_spectral(const RunSpec& requested) {
    auto [scene, probe, result] = stability_run(requested, true);
    const double peng = probe->predicted_limit();
    result.series_columns = {"dt", "rho"};
    for (int k = 0; k < spectral_points; ++k) {
        const double dt = peng / 30.0 * std::pow(90.0, k / double(spectral_points - 1));
        double rho = std::numeric_limits<double>::infinity();  // a scheme that throws has no bounded step map
        try {
            rho = spectral_radius(*scene, step_jacobian(*scene, requested.scheme, dt));
        } catch (...) {}
        result.series.push_back({dt, rho});
    }
    return unless_interrupted(std::move(result));
}

}  // namespace rotbench
