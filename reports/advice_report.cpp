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
    out += a.verdict + "\n\n";
    const bool verified = !a.recommendations.empty() && a.recommendations.front().verified;
    out += fmt::format("{:<4} {:<18} {:>10} {:>12} {:>7} {:>10} {:>6} {:>10} {:>10} {:>9} {:>11}{}  how\n", "rank", "scheme", "dt (s)",
                       "limit (s)", "x Peng", "predicted", "order", "exact rot", "limited by", "ns/step", "CPU s / s",
                       verified ? "   verified  stable" : "");
    int rank = 0;
    for (const auto& r : a.recommendations) {
        out += fmt::format("{:<4} {:<18} {:>10.3e} {:>12} {:>7.2f} {:>10.2e} {:>6} {:>10} {:>10} {:>9.0f} {:>11.3e}", ++rank, r.scheme, r.dt,
                           std::isinf(r.dt_stability) ? "none found" : fmt::format("{:.3e}", r.dt_stability), r.stability_ratio,
                           r.predicted_error, std::isnan(r.order) ? "-" : fmt::format("{:.2f}", r.order),
                           std::isnan(r.exact_rotation_error) ? "-" : fmt::format("{:.2e}", r.exact_rotation_error), r.limited_by,
                           r.ns_per_step, r.cpu_seconds);
        if (r.verified) out += fmt::format(" {:>10.2e}  {:>6}", r.verified_error, r.verified_stable ? "yes" : "NO");
        out += "  " + r.how + "\n";
    }
    if (a.recommendations.empty()) out += "(no scheme meets the tolerance)\n";
    else out += fmt::format("\n\"exact rot\": the error at the same dt of {}, whose rotation between the torque kicks is the exact "
                            "free-body flow: the part of the error the rotation scheme is not responsible for.\nladders (dt s: "
                            "relative error; - unstable):\n", advice_exact_rotation);
    for (const auto& r : a.recommendations) {
        out += fmt::format("  {:<18}", r.scheme);
        for (const auto& rung : r.ladder)
            out += std::isnan(rung.error) ? fmt::format(" {:.2e}: -", rung.dt) : fmt::format(" {:.2e}: {:.2e}", rung.dt, rung.error);
        out += "\n";
    }
    for (const auto& [scheme, why] : a.not_recommended) out += fmt::format("not recommended: {}: {}\n", scheme, why);
    return out;
}

std::string advice_json(const Advice& a) {
    using json = nlohmann::ordered_json;
    const auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
    json recommendations = json::array(), rejected = json::array();
    for (const auto& r : a.recommendations) {
        json ladder = json::array();
        for (const auto& rung : r.ladder) ladder.push_back({{"dt", rung.dt}, {"error", number(rung.error)}});
        recommendations.push_back({{"scheme", r.scheme},
                                   {"dt", r.dt},
                                   {"dt_stability", number(r.dt_stability)},
                                   {"stability_over_peng", number(r.stability_ratio)},
                                   {"predicted_error", r.predicted_error},
                                   {"how", r.how},
                                   {"limited_by", r.limited_by},
                                   {"ladder", ladder},
                                   {"order", number(r.order)},
                                   {"order_interval", {number(r.order_lo), number(r.order_hi)}},
                                   {"exact_rotation_error", number(r.exact_rotation_error)},
                                   {"contact_share", number(r.contact_share)},
                                   {"ns_per_step", number(r.ns_per_step)},
                                   {"cpu_seconds", number(r.cpu_seconds)},
                                   {"verified_error", r.verified ? number(r.verified_error) : json(nullptr)},
                                   {"verified_stable", r.verified ? json(r.verified_stable) : json(nullptr)}});
    }
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
                      {"verdict", a.verdict},
                      {"exact_rotation_scheme", advice_exact_rotation},
                      {"recommendations", recommendations},
                      {"not_recommended", rejected}};
    return doc.dump(2) + "\n";
}

}  // namespace rotbench
