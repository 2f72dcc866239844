#include "reports/results_csv.hpp"

#include "reports/output_files.hpp"

namespace rotbench {

std::string results_csv(const std::vector<RunResult>& results) {
    std::string csv = "scene,scheme,dt,metric,value\n";
    for (const auto& r : results)
        for (const auto& [metric, value] : r.metrics)
            csv += r.spec.scene + "," + r.spec.scheme + "," + format_number(r.spec.dt) + "," + metric + "," +
                   format_number(value) + "\n";
    return csv;
}

}  // namespace rotbench
