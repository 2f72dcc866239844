#include "harness/analysis/sweep_plan.hpp"

#include "harness/analysis/claims.hpp"
#include "harness/analysis/ensemble.hpp"
#include "harness/exec/machine.hpp"
#include "harness/exec/run.hpp"
#include "harness/store/client.hpp"
#include "references/trajectory.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace rotbench {

namespace {

// A run keeps its reference at every step in memory (Trajectory::width doubles per body-step;
// the Odeint one is also what the reference cache stores). A plan whose reference would not
// fit in half the machine is refused before it starts, not killed by the system halfway.
void check_reference_fits(const Scene& scene, double dt, std::int64_t steps) {
    if (!scene.has_reference()) return;
    const double bodies = static_cast<double>(scene.initial_state().size());
    const double per_step = static_cast<double>(Trajectory::width * sizeof(double));
    const double bytes = (static_cast<double>(steps) + 1.0) * bodies * per_step;
    if (bytes <= memory_bytes() / 2) return;
    throw InputError(
        fmt::format("{} at dt {:g}: its reference would take {:.0f} GB of memory ({:.3g} steps x {:g} bodies x {:g} B), "
                    "more than half of this machine's {:.0f} GB; use a larger --dt or a shorter --t-end",
                    scene.params.owner(), dt, std::ceil(bytes / 1e9), static_cast<double>(steps), bodies, per_step, memory_bytes() / 1e9));
}

}  // namespace

std::vector<RunSpec> plan_sweep(const SweepSpec& spec, std::vector<std::string>* skipped) {
    const auto& scenes = SceneRegistry::instance();
    const auto& schemes = SchemeRegistry::instance();
    std::vector<std::string> scene_ids = spec.scenes;
    if (scene_ids.empty())
        for (const auto& id : scenes.ids())
            if (scenes.at(id, "scene").extra.in_default_suite) scene_ids.push_back(id);
    if (spec.ensemble < 1 || spec.ensemble > 1000) throw InputError(fmt::format("--ensemble must be 1 to 1000, got {}", spec.ensemble));
    const auto scheme_ids = spec.schemes.empty() ? schemes.ids() : spec.schemes;
    for (const auto& id : scheme_ids) schemes.at(id, "scheme");
    for (const auto& [scene_id, overrides] : spec.params) {
        scenes.at(scene_id, "scene");
        if (std::find(scene_ids.begin(), scene_ids.end(), scene_id) == scene_ids.end())
            throw InputError("parameters are set for scene '" + scene_id + "', which is not selected");
    }

    std::vector<RunSpec> plan;
    for (const auto& scene_id : scene_ids) {
        const auto found = spec.params.find(scene_id);
        ParamOverrides overrides = spec.quick ? make_scene(scene_id)->quick_params() : ParamOverrides{};
        if (found != spec.params.end()) overrides.insert(overrides.end(), found->second.begin(), found->second.end());
        ParamOverrides with_t_end = overrides;
        if (spec.t_end > 0.0) with_t_end.push_back({"t_end", {spec.t_end}});
        const auto scene = make_scene(scene_id, with_t_end);  // validates every override
        const double t_end = scene->t_end();
        const auto dts = !spec.dts.empty() ? spec.dts : spec.quick ? scene->quick_dts() : scene->default_dts();
        for (double dt : dts) check_reference_fits(*scene, dt, step_count(t_end, dt));  // validates dt against t_end
        const auto& keys = scene->params.entries();
        const bool seeded = std::any_of(keys.begin(), keys.end(), [](const auto& e) { return e.key == "seed"; });
        const int members = seeded ? spec.ensemble : 1;
        if (members > 1) try {  // the last member's seed checked now, not once the others have run
                make_scene(scene_id, ensemble_member(with_t_end, scene->params.number("seed"), members - 1));
            } catch (const InputError& e) {
                throw InputError(fmt::format("--ensemble {} from seed {:.0f}: {}", members, scene->params.number("seed"), e.what()));
            }
        const bool horizon = judges_energy(scene_info(*scene));
        for (const auto& scheme_id : scheme_ids) {
            if (const std::string why = why_not_taken(scheme_id, scene_id); !why.empty()) {
                if (skipped) skipped->push_back(why);
                continue;
            }
            for (double dt : dts)
                for (int k = 0; k < members; ++k)
                    plan.push_back({scene_id, scheme_id, dt, t_end,
                                    members > 1 ? ensemble_member(overrides, scene->params.number("seed"), k) : overrides});
            if (horizon) plan.push_back(horizon_run({scene_id, scheme_id, *std::max_element(dts.begin(), dts.end()), t_end, overrides}));
        }
    }
    return plan;
}

}  // namespace rotbench
