#include "reports/clients_report.hpp"


#include <cmath>
#include <fmt/format.h>

namespace rotbench {

std::string clients_section(const std::vector<CounterpartVerdict>& verdicts) {
    if (verdicts.empty()) return "";
    std::string md = "## " + clients_heading + "\n\n";
    md += "Each client's run is compared at every step with its counterpart's run on the same scene at the same dt "
          "(`counterpart_omega_diff_max`, `counterpart_angle_diff_max`); its claims are judged in the verdicts above. "
          "The same map differs by round-off only: at most 10 eps per step times |w_ref| in w, 10 eps per step in angle.\n\n";
    md += "| client | counterpart | scene | max \\|Δw\\| / \\|w_ref\\| at the coarsest dt | max angle (rad) | finest dt | max \\|Δw\\| / \\|w_ref\\| | the map |\n";
    md += "|---|---|---|---|---|---|---|---|\n";
    for (const auto& v : verdicts) {
        std::string map = "the same, to round-off";
        if (std::isnan(CounterpartVerdict::relative(*v.coarse)) || std::isnan(CounterpartVerdict::relative(*v.fine))) {
            map = "not compared: its counterpart gave no trajectory here (a client counterpart that failed, declined or does not take "
                  "the scene)";
        } else if (!v.same_map) {
            map = "another map";
            if (std::isfinite(v.order)) map += fmt::format(": the difference falls as dt^{:.2f}", v.order);
            map += v.note.empty() ? " (not explained by its client file)" : ". " + v.note;
        }
        md += fmt::format("| `{}` | `{}` | `{}` | {:.3g} (dt {:g}) | {:.3g} | {:g} | {:.3g} | {} |\n", v.client, v.counterpart, v.scene,
                          CounterpartVerdict::relative(*v.coarse), v.coarse->spec.dt, v.coarse->value(metric::counterpart_angle_diff_max),
                          v.fine->spec.dt, CounterpartVerdict::relative(*v.fine), map);
    }
    return md + "\n";
}

}  // namespace rotbench
