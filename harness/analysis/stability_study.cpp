#include "harness/analysis/stability_study.hpp"

#include "harness/exec/run_kinds.hpp"
#include "harness/scenes/contact_pair.hpp"
#include "harness/scenes/stability_probe.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/client.hpp"
#include "harness/store/parse.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

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

namespace {

// The parameter a stability case varies: the damping ratio of a contact, fast_spin's spin rate.
std::string varied(const std::string& scene) { return scene == "fast_spin" ? "omega_max" : "zeta"; }

bool linearisable(const Scene& scene) { return dynamic_cast<const StabilityProbe&>(scene).linearisable_at_rest(); }

// The index of the row a stability or amplification run belongs to, made (with the scene's predictions) if new.
std::size_t row_of(StabilityStudy& study, const RunSpec& spec, const std::string& at) {
    const std::string key = varied(spec.scene);
    if (spec.params.size() != 1 || spec.params[0].first != key || spec.params[0].second.size() != 1)
        throw InputError(at + ": its parameters are not one " + key);
    const double value = spec.params[0].second[0];
    const bool spin = key == "omega_max";
    for (std::size_t i = 0; i < study.rows.size(); ++i) {
        const StabilityRow& r = study.rows[i];
        if (r.scene == spec.scene && r.scheme == spec.scheme && (spin ? r.omega_max : r.zeta) == value) return i;
    }
    std::unique_ptr<Scene> scene;
    try {
        scene = make_scene(spec.scene, spec.params);
    } catch (const InputError& e) {
        throw InputError(at + ": " + e.what());
    }
    const auto* pair = dynamic_cast<const ContactPairScene*>(scene.get());
    study.rows.push_back({spec.scene, spec.scheme, spin ? 0.0 : value, spin ? value : 0.0, NAN, NAN,
                          dynamic_cast<const StabilityProbe&>(*scene).predicted_limit(), pair ? pair->verlet_normal_limit() : NAN});
    return study.rows.size() - 1;
}

SpectralCurve curve_of(const RunResult& run) {
    const auto scene = make_scene(run.spec.scene);
    SpectralCurve curve{run.spec.scene, run.spec.scheme, dynamic_cast<const StabilityProbe&>(*scene).predicted_limit(), {}, run.failure};
    const bool whole = run.series.size() == spectral_points &&
                       std::all_of(run.series.begin(), run.series.end(), [](const auto& point) { return point.size() == 2; });
    if (curve.failure.empty() && !whole) curve.failure = "its run did not give a spectral curve";
    if (curve.failure.empty())
        for (const auto& point : run.series) curve.points.push_back({point.at(0), point.at(1)});
    return curve;
}

}  // namespace

std::vector<RunSpec> stability_plan(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                                    const std::vector<double>& zetas, const std::vector<double>& omegas, std::vector<std::string>* skipped) {
    check_stability_scenes(scenes);
    std::vector<RunSpec> plan;
    for (const auto& id : scenes) {
        const std::vector<double>& values = id == "fast_spin" ? omegas : zetas;
        for (double value : values) {
            const ParamOverrides params = {{varied(id), {value}}};
            const auto scene = make_scene(id, params);
            for (const auto& scheme : schemes) {
                if (const std::string why = why_not_taken(scheme, id); !why.empty()) {
                    if (skipped && value == values.front()) skipped->push_back(why);
                    continue;
                }
                plan.push_back({id, scheme, 0.0, scene->t_end(), params, RunKind::stability, false});
                if (linearisable(*scene) && !client_of(scheme))
                    plan.push_back({id, scheme, 0.0, scene->t_end(), params, RunKind::amplification, false});
            }
        }
        const auto scene = make_scene(id);  // the curves: undamped (the contact scenes' default zeta is 0)
        if (linearisable(*scene))
            for (const auto& scheme : schemes)
                if (!client_of(scheme)) plan.push_back({id, scheme, 0.0, scene->t_end(), {}, RunKind::spectral, false});
    }
    return plan;
}

StabilityStudy stability_study(const std::vector<RunResult>& runs, const std::string& name) {
    StabilityStudy study;
    std::set<RunSpec> seen;
    std::vector<std::pair<const RunResult*, const RunResult*>> made;  // each row's search and amplification
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const RunSpec& spec = runs[i].spec;
        const std::string at = fmt::format("{}: run {}", name, i);
        if (!seen.insert(spec).second) throw InputError(at + ": " + spec.scene + " " + spec.scheme + " is there twice");
        try {
            check_stability_scenes({spec.scene});
        } catch (const InputError& e) {
            throw InputError(at + ": " + e.what());
        }
        if (spec.kind == RunKind::spectral) {
            if (!spec.params.empty()) throw InputError(at + ": a spectral curve is undamped, without parameters");
            study.curves.push_back(curve_of(runs[i]));
            continue;
        }
        if (spec.kind != RunKind::stability && spec.kind != RunKind::amplification)
            throw InputError(at + ": a " + kind_name(spec.kind) + " run is not a stability study's");
        const std::size_t row = row_of(study, spec, at);
        made.resize(study.rows.size());
        auto& [search, amplification] = made[row];
        (spec.kind == RunKind::stability ? search : amplification) = &runs[i];
        const double dt = runs[i].value(spec.kind == RunKind::stability ? metric::dt_empirical : metric::dt_amplification);
        if (runs[i].failure.empty() && !(dt >= 0)) throw InputError(at + ": its limit " + format_number(dt) + " is not a time step");
    }
    for (std::size_t i = 0; i < study.rows.size(); ++i) {
        StabilityRow& r = study.rows[i];
        const auto [search, amplification] = made[i];
        if (!search) throw InputError(name + ": " + r.scene + " " + r.scheme + " has an eigenvalue limit and no search");
        r.failure = search->failure;
        r.dt_empirical = search->value(metric::dt_empirical);
        if (amplification) {
            if (r.failure.empty()) r.failure = amplification->failure;
            r.dt_amplification = amplification->value(metric::dt_amplification);
            r.unstable_at_every_dt = amplification->value(metric::unstable_at_every_dt) == 1.0;
        }
        if (!r.failure.empty()) r.dt_empirical = r.dt_amplification = NAN, r.unstable_at_every_dt = false;
    }
    return study;
}

}  // namespace rotbench
