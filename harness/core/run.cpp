#include "harness/core/run.hpp"

#include "harness/core/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rotbench {

bool RunResult::has(std::string_view name) const {
    return std::any_of(metrics.begin(), metrics.end(), [&](const auto& m) { return m.first == name; });
}

double RunResult::value(std::string_view name) const {
    for (const auto& [n, v] : metrics)
        if (n == name) return v;
    return std::numeric_limits<double>::quiet_NaN();
}

std::int64_t step_count(double t_end, double dt) {
    if (!std::isfinite(dt) || dt <= 0.0) throw InputError(fmt::format("time step must be a positive number, got {}", dt));
    if (!std::isfinite(t_end) || t_end <= 0.0) throw InputError(fmt::format("t-end must be a positive number, got {}", t_end));
    if (t_end < dt) throw InputError(fmt::format("t-end {} is shorter than the time step {}", t_end, dt));
    const double ratio = t_end / dt;
    const double nearest = std::round(ratio);
    const double steps = std::abs(ratio - nearest) <= 1e-9 * ratio ? nearest : std::ceil(ratio);
    if (steps > 1e12) throw InputError(fmt::format("t-end / dt = {:.3g} steps is too many", steps));
    return static_cast<std::int64_t>(steps);
}

namespace {
constexpr RunKind all_kinds[] = {RunKind::trajectory,    RunKind::reversal, RunKind::stability, RunKind::horizon,
                                 RunKind::amplification, RunKind::spectral, RunKind::states, RunKind::cost};
}

const char* kind_name(RunKind kind) {
    switch (kind) {
        case RunKind::trajectory: return "trajectory";
        case RunKind::reversal: return "reversal";
        case RunKind::stability: return "stability";
        case RunKind::horizon: return "horizon";
        case RunKind::amplification: return "amplification";
        case RunKind::spectral: return "spectral";
        case RunKind::states: return "states";
        case RunKind::cost: return "cost";
    }
    return "?";
}

RunKind kind_from_name(const std::string& name) {
    std::string valid;
    for (RunKind k : all_kinds) {
        if (name == kind_name(k)) return k;
        valid += (valid.empty() ? "" : ", ") + std::string(kind_name(k));
    }
    throw InputError("unknown run kind '" + name + "'; valid kinds: " + valid);
}

double relative_omega_error(const RunResult& r) { return r.value(metric::omega_err_max) / r.value(metric::omega_ref_max); }

}  // namespace rotbench
