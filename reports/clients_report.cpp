#include "reports/clients_report.hpp"

#include "harness/analysis/round_off.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>

namespace rotbench {

std::string clients_section(const ResultSet& set) {
    // client -> scene -> its runs with a measured difference, by dt
    std::map<std::string, std::map<std::string, std::map<double, const RunResult*>>> found;
    for (const auto& r : set.runs) {
        const SchemeInfo* info = set.scheme(r.spec.scheme);
        if (info && !info->counterpart.empty() && r.has(metric::counterpart_omega_diff_max)) found[r.spec.scheme][r.spec.scene][r.spec.dt] = &r;
    }
    if (found.empty()) return "";
    std::string md = "## " + clients_heading + "\n\n";
    md += "Each client's run is compared at every step with its counterpart's run on the same scene at the same dt "
          "(`counterpart_omega_diff_max`, `counterpart_angle_diff_max`); its claims are judged in the verdicts above. "
          "The same map differs by round-off only: at most 10 eps per step times |w_ref| in w, 10 eps per step in angle.\n\n";
    md += "| client | counterpart | scene | max \\|Δw\\| / \\|w_ref\\| at the coarsest dt | max angle (rad) | finest dt | max \\|Δw\\| / \\|w_ref\\| | the map |\n";
    md += "|---|---|---|---|---|---|---|---|\n";
    for (const auto& [client, scenes] : found)
        for (const auto& [scene, by_dt] : scenes) {
            const RunResult& coarse = *by_dt.rbegin()->second;
            const RunResult& fine = *by_dt.begin()->second;
            const auto relative = [](const RunResult& r) { return r.value(metric::counterpart_omega_diff_max) / r.value(metric::omega_ref_max); };
            bool same = true;
            for (const auto& [dt, r] : by_dt)
                same = same && r->value(metric::counterpart_omega_diff_max) <= round_off_bound(*r, metric::counterpart_omega_diff_max) &&
                       r->value(metric::counterpart_angle_diff_max) <= round_off_bound(*r, metric::counterpart_angle_diff_max);
            std::string verdict = "the same, to round-off";
            if (!same) {
                verdict = "another map";
                if (by_dt.size() > 1 && relative(fine) > 0 && relative(coarse) > 0)
                    verdict += fmt::format(": the difference falls as dt^{:.2f}",
                                           std::log(relative(coarse) / relative(fine)) / std::log(coarse.spec.dt / fine.spec.dt));
                const std::string& why = set.scheme(client)->counterpart_note;
                verdict += why.empty() ? " (not explained by its client file)" : ". " + why;
            }
            md += fmt::format("| `{}` | `{}` | `{}` | {:.3g} (dt {:g}) | {:.3g} | {:g} | {:.3g} | {} |\n", client,
                              set.scheme(client)->counterpart, scene, relative(coarse), coarse.spec.dt,
                              coarse.value(metric::counterpart_angle_diff_max), fine.spec.dt, relative(fine), verdict);
        }
    return md + "\n";
}

}  // namespace rotbench
