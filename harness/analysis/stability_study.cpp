#include "harness/analysis/stability_study.hpp"

#include "harness/engine/parallel.hpp"
#include "harness/scenes/contact_pair.hpp"
#include "harness/analysis/stability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <fmt/format.h>
#include <map>

namespace rotbench {

std::string stability_kind(const StabilityRow& row) {
    if (row.unstable_at_every_dt || row.dt_empirical == 0.0) return "weak";
    if (std::isinf(row.dt_empirical)) return "none";
    return "sharp";
}

namespace {

ParamOverrides overrides(const StabilityRow& r) {
    return r.omega_max > 0 ? ParamOverrides{{"omega_max", {r.omega_max}}} : ParamOverrides{{"zeta", {r.zeta}}};
}

}  // namespace

void check_stability_scenes(const std::vector<std::string>& scenes) {
    std::vector<std::string> valid;
    for (const auto& id : SceneRegistry::instance().ids())
        if (dynamic_cast<const StabilityProbe*>(make_scene(id).get())) valid.push_back(id);
    for (const auto& scene : scenes)
        if (std::find(valid.begin(), valid.end(), scene) == valid.end())
            throw InputError("scene '" + scene + "' is not a stability scene; valid: " + join(valid, ", "));
}

std::size_t stability_case_count(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                                 const std::vector<double>& zetas, const std::vector<double>& omegas) {
    std::size_t count = 0;
    for (const auto& scene : scenes) count += (scene == "fast_spin" ? omegas.size() : zetas.size()) * schemes.size();
    return count;
}

std::vector<StabilityRow> stability_study(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                                          const std::vector<double>& zetas, const std::vector<double>& omegas, int jobs,
                                          Progress* progress) {
    check_stability_scenes(scenes);
    std::vector<StabilityRow> rows;
    for (const auto& scene : scenes) {
        const bool spin = scene == "fast_spin";
        for (double value : spin ? omegas : zetas)
            for (const auto& scheme : schemes) rows.push_back({scene, scheme, spin ? 0.0 : value, spin ? value : 0.0});
    }
    parallel_for(rows.size(), jobs, [&](std::size_t i) {
        StabilityRow& r = rows[i];
        if (progress) progress->started(i, r.scheme + " on " + r.scene);
        struct Finish {  // also when the case throws
            Progress* progress;
            std::size_t i;
            ~Finish() {
                if (progress) progress->finished(i);
            }
        } finish{progress, i};
        const auto scene = make_scene(r.scene, overrides(r));
        const auto& probe = dynamic_cast<const StabilityProbe&>(*scene);
        const StabilityCriterion c{stability_horizon_periods * probe.period(), stability_growth};
        r.dt_peng = probe.predicted_limit();
        const auto* pair = dynamic_cast<const ContactPairScene*>(scene.get());
        r.dt_verlet_normal = pair ? pair->verlet_normal_limit() : NAN;
        r.dt_empirical = empirical_limit(*scene, r.scheme, r.dt_peng, c);
        if (probe.linearisable_at_rest()) {
            r.dt_amplification = amplification_limit(*scene, r.scheme, r.dt_peng, c);
            r.unstable_at_every_dt = unstable_at_every_dt(*scene, r.scheme, 0.01 * r.dt_peng);
        } else {
            r.dt_amplification = NAN;
        }
    });
    return rows;
}

std::vector<SpectralCurve> spectral_radius_curves(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes) {
    std::vector<SpectralCurve> curves;
    for (const auto& id : scenes) {
        const auto scene = make_scene(id);  // the contact scenes default to zeta = 0
        const auto* probe = dynamic_cast<const StabilityProbe*>(scene.get());
        if (!probe || !probe->linearisable_at_rest()) continue;
        for (const auto& scheme : schemes) {
            SpectralCurve curve{id, scheme, probe->predicted_limit(), {}};
            for (int k = 0; k <= 40; ++k) {
                const double dt = probe->predicted_limit() / 30.0 * std::pow(90.0, k / 40.0);
                double rho = std::numeric_limits<double>::infinity();  // a scheme that throws has no bounded step map
                try {
                    rho = spectral_radius(*scene, step_jacobian(*scene, scheme, dt));
                } catch (...) {
                }
                curve.points.push_back({dt, rho});
            }
            curves.push_back(std::move(curve));
        }
    }
    return curves;
}

}  // namespace rotbench
