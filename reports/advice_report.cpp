#include "reports/advice_report.hpp"

#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace rotbench {

std::string advice_table(const Advice& a) {
    const auto& p = a.particle;
    std::string out = fmt::format(
        "particle: I = ({:g}, {:g}, {:g}) kg m^2, m = {:g} kg, k = {:g} N/m, zeta = {:g}, w = {:g} rad/s; contact period {:.3g} s, "
        "Peng's dt {:.3g} s; {:g} s simulated; tolerance {:g} (relative angular-velocity error)\n\n",
        p.inertia.x(), p.inertia.y(), p.inertia.z(), p.mass, p.stiffness, p.zeta, p.omega, a.period, a.dt_peng, a.t_end, a.tolerance);
    const bool verified = !a.recommendations.empty() && a.recommendations.front().verified;
    out += fmt::format("{:<4} {:<18} {:>10} {:>12} {:>10} {:>9} {:>11}{}  how\n", "rank", "scheme", "dt (s)", "limit (s)", "predicted",
                       "ns/step", "CPU s / s", verified ? "   verified  stable" : "");
    int rank = 0;
    for (const auto& r : a.recommendations) {
        out += fmt::format("{:<4} {:<18} {:>10.3e} {:>12} {:>10.2e} {:>9.0f} {:>11.3e}", ++rank, r.scheme, r.dt,
                           std::isinf(r.dt_stability) ? "none found" : fmt::format("{:.3e}", r.dt_stability), r.predicted_error,
                           r.ns_per_step, r.cpu_seconds);
        if (r.verified) out += fmt::format(" {:>10.2e}  {:>6}", r.verified_error, r.verified_stable ? "yes" : "NO");
        out += "  " + r.how + "\n";
    }
    if (a.recommendations.empty()) out += "(no scheme meets the tolerance)\n";
    for (const auto& [scheme, why] : a.not_recommended) out += fmt::format("not recommended: {}: {}\n", scheme, why);
    return out;
}

std::string advice_json(const Advice& a) {
    using json = nlohmann::ordered_json;
    const auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    json recommendations = json::array(), rejected = json::array();
    for (const auto& r : a.recommendations)
        recommendations.push_back({{"scheme", r.scheme},
                                   {"dt", r.dt},
                                   {"dt_stability", number(r.dt_stability)},
                                   {"predicted_error", r.predicted_error},
                                   {"how", r.how},
                                   {"ns_per_step", number(r.ns_per_step)},
                                   {"cpu_seconds", number(r.cpu_seconds)},
                                   {"verified_error", r.verified ? number(r.verified_error) : json(nullptr)},
                                   {"verified_stable", r.verified ? json(r.verified_stable) : json(nullptr)}});
    for (const auto& [scheme, why] : a.not_recommended) rejected.push_back({{"scheme", scheme}, {"why", why}});
    const auto& p = a.particle;
    const json doc = {{"particle",
                       {{"inertia", {p.inertia.x(), p.inertia.y(), p.inertia.z()}},
                        {"mass", p.mass},
                        {"stiffness", p.stiffness},
                        {"zeta", p.zeta},
                        {"omega", p.omega}}},
                      {"tolerance", a.tolerance},
                      {"t_end", a.t_end},
                      {"contact_period", a.period},
                      {"dt_peng", a.dt_peng},
                      {"recommendations", recommendations},
                      {"not_recommended", rejected}};
    return doc.dump(2) + "\n";
}

}  // namespace rotbench
