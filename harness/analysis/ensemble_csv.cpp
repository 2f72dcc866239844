#include "harness/analysis/ensemble_csv.hpp"

#include "harness/analysis/ensemble.hpp"
#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"

namespace rotbench {

std::string ensemble_csv(const std::vector<RunResult>& runs) {
    const std::vector<bool> members = ensemble_members(runs);
    std::string csv;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (!members[i]) continue;
        const RunResult& r = runs[i];
        for (const auto& [metric, value] : r.metrics)
            csv += csv_record({r.spec.scene, r.spec.scheme, format_number(r.spec.dt), format_number(member_seed(r.spec)), metric,
                               format_number(value)});
    }
    return csv.empty() ? csv : "scene,scheme,dt,seed,metric,value\n" + csv;
}

}  // namespace rotbench
