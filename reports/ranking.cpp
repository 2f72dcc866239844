#include "reports/ranking.hpp"


#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {

CostToTolerance cost_to_tolerance(const std::vector<const RunResult*>& runs, const OrderFit& fit, double tolerance) {
    std::vector<const RunResult*> ok;
    for (const RunResult* r : runs)
        if (r->failure.empty() && std::isfinite(r->value("omega_err_max")) && std::isfinite(r->value("ns_per_step"))) ok.push_back(r);
    std::sort(ok.begin(), ok.end(), [](const RunResult* a, const RunResult* b) { return a->spec.dt > b->spec.dt; });
    if (ok.empty()) return {INFINITY, "never"};
    const auto seconds_at = [](const RunResult* r, double dt) {
        const double duration = r->value("steps") * r->spec.dt;
        return r->value("ns_per_step") * 1e-9 * duration / dt;
    };
    for (std::size_t i = 0; i < ok.size(); ++i) {
        if (ok[i]->value("omega_err_max") > tolerance) continue;
        if (i == 0) return {seconds_at(ok[0], ok[0]->spec.dt), "at most"};
        const RunResult *a = ok[i - 1], *b = ok[i];
        const double la = std::log(a->value("omega_err_max")), lb = std::log(b->value("omega_err_max"));
        const double w = (std::log(tolerance) - lb) / (la - lb);  // 0 at b, 1 at a
        const double dt = std::exp(std::log(b->spec.dt) + w * (std::log(a->spec.dt) - std::log(b->spec.dt)));
        return {seconds_at(b, dt), "interpolated"};
    }
    if (!fit.sufficient || fit.order <= 0.1) return {INFINITY, "never"};
    const RunResult* finest = ok.back();
    const double dt = finest->spec.dt * std::pow(tolerance / finest->value("omega_err_max"), 1.0 / fit.order);
    return {seconds_at(finest, dt), "extrapolated"};
}

std::string ranking_section(const ResultSet& set, const std::vector<OrderRow>& orders) {
    const std::vector<RunResult>& results = set.runs;
    const std::vector<std::string> scenes = {"asymmetric_free", "dipole_top"};
    std::vector<std::string> schemes;
    for (const auto& r : results)
        if (std::find(schemes.begin(), schemes.end(), r.spec.scheme) == schemes.end()) schemes.push_back(r.spec.scheme);
    for (const auto& s : scenes)
        if (std::none_of(results.begin(), results.end(), [&](const RunResult& r) { return r.spec.scene == s; })) return "";

    struct Row {
        std::string scheme;
        std::vector<CostToTolerance> costs;
        double score = 0;  // geometric mean of the costs
    };
    std::vector<Row> rows;
    for (const auto& scheme : schemes) {
        Row row{scheme, {}, 0};
        double log_sum = 0;
        for (const auto& scene : scenes) {
            std::vector<const RunResult*> runs;
            for (const auto& r : results)
                if (r.spec.scene == scene && r.spec.scheme == scheme) runs.push_back(&r);
            OrderFit fit;
            for (const auto& o : orders)
                if (o.scene == scene && o.scheme == scheme && o.metric == "omega_err_max") fit = o.fit;
            row.costs.push_back(cost_to_tolerance(runs, fit, ranking_tolerance));
            log_sum += std::log(row.costs.back().seconds);
        }
        row.score = std::exp(log_sum / scenes.size());
        rows.push_back(row);
    }
    std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.score < b.score; });
    const auto direct = std::find_if(rows.begin(), rows.end(), [](const Row& r) { return r.scheme == "direct"; });
    const double direct_score = direct == rows.end() ? NAN : direct->score;

    std::string md = fmt::format(
        "## Ranking: CPU time to reach an angular-velocity error of {:g} rad/s\n\n"
        "For each scheme, the CPU time of a whole run at the step that just reaches `omega_err_max` = {:g} rad/s, on the "
        "free asymmetric top (|w| ~ 1 rad/s, 20 s) and on the dipole top (torque T(q), 10 s). The step is interpolated "
        "(log-log) between the two measured steps around the tolerance; \"at most\" means the coarsest step measured "
        "already reaches it; \"extrapolated\" means no measured step does, and the finest one is extended with the "
        "observed order. Schemes are ranked by the geometric mean of the two times; \"never\" (no convergence) ranks "
        "last. Times are from `ns_per_step` (medians) in this run, so ratios between schemes are what to read.\n\n"
        "| rank | scheme | asymmetric_free (s) | dipole_top (s) | geometric mean / direct | note |\n"
        "|---:|---|---:|---:|---:|---|\n",
        ranking_tolerance, ranking_tolerance);
    int rank = 0;
    for (const auto& row : rows) {
        const auto show = [](const CostToTolerance& c) {
            if (!std::isfinite(c.seconds)) return std::string("never");
            return fmt::format("{:.2e}{}", c.seconds, c.how == "interpolated" ? "" : " (" + c.how + ")");
        };
        std::string note;
        if (const SchemeInfo* info = set.scheme(row.scheme); info && !info->claims.sound)
            note = "negative control: does not converge";
        md += fmt::format("| {} | `{}` | {} | {} | {} | {} |\n", ++rank, row.scheme, show(row.costs[0]), show(row.costs[1]),
                          std::isfinite(row.score) ? fmt::format("{:.3g}", row.score / direct_score) : "—", note);
    }
    return md + "\n";
}

}  // namespace rotbench
