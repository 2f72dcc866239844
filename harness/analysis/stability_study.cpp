#include "harness/analysis/stability_study.hpp"

#include "harness/engine/isolation.hpp"
#include "harness/engine/parallel.hpp"
#include "harness/scenes/contact_pair.hpp"
#include "harness/scenes/stability_probe.hpp"
#include "harness/analysis/stability.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <limits>
#include <fmt/format.h>
#include <map>

namespace rotbench {

std::string stability_kind(const StabilityRow& row) {
    if (!row.failure.empty()) return "failed";
    if (row.unstable_at_every_dt || row.dt_empirical == 0.0) return "weak";
    if (std::isinf(row.dt_empirical)) return "none";
    return "sharp";
}

namespace {

ParamOverrides overrides(const StabilityRow& r) {
    return r.omega_max > 0 ? ParamOverrides{{"omega_max", {r.omega_max}}} : ParamOverrides{{"zeta", {r.zeta}}};
}

void fail(StabilityRow& r, const std::string& why) {
    r.failure = why;
    r.dt_empirical = r.dt_amplification = NAN;
    r.unstable_at_every_dt = false;
}

// The numbers of a worker's text, each read whole; none if any is not a number.
std::vector<double> numbers_of(const std::string& text) {
    std::vector<double> values;
    std::istringstream in(text);
    for (std::string word; in >> word;) {
        char* end = nullptr;
        const double v = std::strtod(word.c_str(), &end);
        if (end != word.c_str() + word.size()) return {};
        values.push_back(v);
    }
    return values;
}

void read_stability_case_text(const std::string& text, StabilityRow& r) {
    const auto v = numbers_of(text);
    if (v.size() != 5 || (v[4] != 0.0 && v[4] != 1.0)) return fail(r, "its worker's output was not a stability case");
    r.dt_empirical = v[0], r.dt_amplification = v[1];  // v[2], v[3]: the scene's own, already in the row
    r.unstable_at_every_dt = v[4] == 1.0;
}

// The limits that come from the row's scene alone (no scheme runs): Peng's and Verlet's.
void predicted_limits(StabilityRow& r, const Scene& scene) {
    r.dt_peng = dynamic_cast<const StabilityProbe&>(scene).predicted_limit();
    const auto* pair = dynamic_cast<const ContactPairScene*>(&scene);
    r.dt_verlet_normal = pair ? pair->verlet_normal_limit() : NAN;
}

// The 41 steps of a spectral curve, from 1/30 to 3 times Peng's prediction.
constexpr int spectral_points = 41;
double spectral_dt(double dt_peng, int k) { return dt_peng / 30.0 * std::pow(90.0, k / double(spectral_points - 1)); }

}  // namespace

void check_stability_scenes(const std::vector<std::string>& scenes) {
    const std::vector<std::string> valid = stability_scene_ids();
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
                                          Progress* progress, const StabilityLimits& limits) {
    check_stability_scenes(scenes);
    std::vector<StabilityRow> rows;
    for (const auto& scene : scenes) {
        const bool spin = scene == "fast_spin";
        for (double value : spin ? omegas : zetas)
            for (const auto& scheme : schemes) rows.push_back({scene, scheme, spin ? 0.0 : value, spin ? value : 0.0});
    }
    const std::size_t megabytes = limits.megabytes ? limits.megabytes : isolation_memory(jobs);
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
        if (!isolated(r.scheme)) return measure_stability_case(r);
        predicted_limits(r, *make_scene(r.scene, overrides(r)));  // the row keeps them whatever the worker does
        std::vector<std::string> args = {"__stability", "--scene", r.scene, "--scheme", r.scheme};
        if (r.omega_max > 0) args.insert(args.end(), {"--omega-max", fmt::format("{:.17g}", r.omega_max)});
        else args.insert(args.end(), {"--zeta", fmt::format("{:.17g}", r.zeta)});
        const WorkerOutput out = run_worker(args, limits.seconds, megabytes);
        if (out.failure.empty() && !out.interrupted) read_stability_case_text(out.text, r);
        else fail(r, out.interrupted ? "interrupted" : out.failure);
    });
    return rows;
}

void measure_stability_case(StabilityRow& r) {
    const auto scene = make_scene(r.scene, overrides(r));
    const auto& probe = dynamic_cast<const StabilityProbe&>(*scene);
    const StabilityCriterion c = stability_criterion(probe);
    predicted_limits(r, *scene);
    r.dt_empirical = empirical_limit(*scene, r.scheme, r.dt_peng, c);
    if (probe.linearisable_at_rest()) {
        r.dt_amplification = amplification_limit(*scene, r.scheme, r.dt_peng, c);
        r.unstable_at_every_dt = unstable_at_every_dt(*scene, r.scheme, 0.01 * r.dt_peng);
    } else {
        r.dt_amplification = NAN;
    }
}

// One line of five numbers, every bit kept (%.17g reads back exactly).
std::string stability_case_text(const StabilityRow& r) {
    return fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} {}\n", r.dt_empirical, r.dt_amplification, r.dt_peng, r.dt_verlet_normal,
                       r.unstable_at_every_dt ? 1 : 0);
}

std::string spectral_curve_text(const std::string& scene_id, const std::string& scheme) {
    const auto scene = make_scene(scene_id);  // the contact scenes default to zeta = 0
    const double dt_peng = dynamic_cast<const StabilityProbe&>(*scene).predicted_limit();
    std::string text;
    for (int k = 0; k < spectral_points; ++k) {
        double rho = std::numeric_limits<double>::infinity();  // a scheme that throws has no bounded step map
        try {
            rho = spectral_radius(*scene, step_jacobian(*scene, scheme, spectral_dt(dt_peng, k)));
        } catch (...) {
        }
        text += fmt::format("{:.17g}\n", rho);
    }
    return text;
}

std::vector<SpectralCurve> spectral_radius_curves(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                                                  const StabilityLimits& limits) {
    std::vector<SpectralCurve> curves;
    for (const auto& id : scenes) {
        const auto scene = make_scene(id);
        const auto* probe = dynamic_cast<const StabilityProbe*>(scene.get());
        if (!probe || !probe->linearisable_at_rest()) continue;
        for (const auto& scheme : schemes) {
            SpectralCurve curve{id, scheme, probe->predicted_limit(), {}, {}};
            std::string text;
            if (!isolated(scheme)) {
                text = spectral_curve_text(id, scheme);
            } else {
                const WorkerOutput out = run_worker({"__stability", "--scene", id, "--scheme", scheme, "--spectral"}, limits.seconds,
                                                    limits.megabytes ? limits.megabytes : isolation_memory(1));
                text = out.text;
                curve.failure = out.interrupted ? "interrupted" : out.failure;
            }
            const auto rho = numbers_of(text);
            if (curve.failure.empty() && rho.size() != spectral_points) curve.failure = "its worker's output was not a spectral curve";
            if (curve.failure.empty())
                for (int k = 0; k < spectral_points; ++k) curve.points.push_back({spectral_dt(curve.dt_peng, k), rho[k]});
            curves.push_back(std::move(curve));
        }
    }
    return curves;
}

}  // namespace rotbench
