#include "harness/sweep.hpp"

namespace rotbench {

std::vector<RunSpec> plan_sweep(const SweepSpec& spec) {
    const auto& scenes = SceneRegistry::instance();
    const auto& schemes = SchemeRegistry::instance();
    const auto scene_ids = spec.scenes.empty() ? scenes.ids() : spec.scenes;
    const auto scheme_ids = spec.schemes.empty() ? schemes.ids() : spec.schemes;
    for (const auto& id : scheme_ids) schemes.at(id, "scheme");

    std::vector<RunSpec> plan;
    for (const auto& scene_id : scene_ids) {
        const auto scene = scenes.at(scene_id, "scene").make();
        const double t_end = spec.t_end > 0.0 ? spec.t_end : scene->default_t_end();
        const auto dts = spec.dts.empty() ? scene->default_dts() : spec.dts;
        for (double dt : dts) step_count(t_end, dt);  // validates dt against t_end
        for (const auto& scheme_id : scheme_ids)
            for (double dt : dts) plan.push_back({scene_id, scheme_id, dt, t_end});
    }
    return plan;
}

std::vector<RunResult> run_sweep(const std::vector<RunSpec>& plan, const RunOptions& options,
                                 const std::function<void(const RunResult&)>& on_done) {
    std::vector<RunResult> results;
    results.reserve(plan.size());
    for (const auto& spec : plan) {
        results.push_back(run_one(spec, options));
        if (on_done) on_done(results.back());
    }
    return results;
}

}  // namespace rotbench
