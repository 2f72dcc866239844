#include "harness/analysis/stability_study.hpp"

#include "harness/exec/run_kinds.hpp"
#include "harness/scenes/contact_pair.hpp"
#include "harness/scenes/stability_probe.hpp"
#include "harness/store/parse.hpp"

#include <algorithm>
#include <cmath>

namespace rotbench {

std::string stability_kind(const StabilityRow& row) {
    if (!row.failure.empty()) return "failed";
    if (row.unstable_at_every_dt || row.dt_empirical == 0.0) return "weak";
    if (std::isinf(row.dt_empirical)) return "none";
    return "sharp";
}

void check_stability_scenes(const std::vector<std::string>& scenes) {
    const std::vector<std::string> valid = stability_scene_ids();
    for (const auto& scene : scenes)
        if (std::find(valid.begin(), valid.end(), scene) == valid.end())
            throw InputError("scene '" + scene + "' is not a stability scene; valid: " + join(valid, ", "));
}

StabilityStudy stability_study(Executor& executor, const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                               const std::vector<double>& zetas, const std::vector<double>& omegas) {
    check_stability_scenes(scenes);
    StabilityStudy study;
    std::vector<RunSpec> tasks;
    std::vector<std::size_t> search_of, amplification_of, curve_of;  // the index of each row's tasks (none: -1) and each curve's
    const auto add = [&](const std::string& scene, const std::string& scheme, double t_end, const ParamOverrides& params, RunKind kind) {
        tasks.push_back({scene, scheme, 0.0, t_end, params, kind, false});
        return tasks.size() - 1;
    };
    for (const auto& id : scenes) {
        const bool spin = id == "fast_spin";
        for (double value : spin ? omegas : zetas) {
            const ParamOverrides params = {{spin ? "omega_max" : "zeta", {value}}};
            const auto scene = make_scene(id, params);
            const auto& probe = dynamic_cast<const StabilityProbe&>(*scene);
            const auto* pair = dynamic_cast<const ContactPairScene*>(scene.get());
            for (const auto& scheme : schemes) {
                study.rows.push_back({id, scheme, spin ? 0.0 : value, spin ? value : 0.0});
                StabilityRow& r = study.rows.back();
                r.dt_peng = probe.predicted_limit();
                r.dt_verlet_normal = pair ? pair->verlet_normal_limit() : NAN;
                r.dt_amplification = NAN;
                search_of.push_back(add(id, scheme, scene->t_end(), params, RunKind::stability));
                amplification_of.push_back(probe.linearisable_at_rest() ? add(id, scheme, scene->t_end(), params, RunKind::amplification)
                                                                        : std::size_t(-1));
            }
        }
        const auto scene = make_scene(id);  // the curves: undamped (the contact scenes' default zeta is 0)
        const auto& probe = dynamic_cast<const StabilityProbe&>(*scene);
        if (!probe.linearisable_at_rest()) continue;
        for (const auto& scheme : schemes) {
            study.curves.push_back({id, scheme, probe.predicted_limit(), {}, {}});
            curve_of.push_back(add(id, scheme, scene->t_end(), {}, RunKind::spectral));
        }
    }

    const std::vector<RunResult> runs = executor.run(tasks);
    if (executor.signal()) return study;
    for (std::size_t i = 0; i < study.rows.size(); ++i) {
        StabilityRow& r = study.rows[i];
        const RunResult& search = runs[search_of[i]];
        r.failure = search.failure;
        r.dt_empirical = search.value(metric::dt_empirical);
        if (const std::size_t a = amplification_of[i]; a < runs.size()) {
            if (r.failure.empty()) r.failure = runs[a].failure;
            r.dt_amplification = runs[a].value(metric::dt_amplification);
            r.unstable_at_every_dt = runs[a].value(metric::unstable_at_every_dt) == 1.0;
        }
        if (!r.failure.empty()) r.dt_empirical = r.dt_amplification = NAN, r.unstable_at_every_dt = false;
    }
    for (std::size_t k = 0; k < study.curves.size(); ++k) {
        SpectralCurve& curve = study.curves[k];
        const RunResult& run = runs[curve_of[k]];
        curve.failure = run.failure;
        const bool whole = run.series.size() == spectral_points &&
                           std::all_of(run.series.begin(), run.series.end(), [](const auto& point) { return point.size() == 2; });
        if (curve.failure.empty() && !whole) curve.failure = "its run did not give a spectral curve";
        if (curve.failure.empty())
            for (const auto& point : run.series) curve.points.push_back({point.at(0), point.at(1)});
    }
    return study;
}

}  // namespace rotbench
