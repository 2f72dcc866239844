#include "harness/analysis/ensemble_csv.hpp"

#include "harness/analysis/ensemble.hpp"
#include "harness/store/csv.hpp"
#include "harness/store/output_files.hpp"

#include <map>

namespace rotbench {

std::string ensemble_csv(const std::vector<RunResult>& runs) {
    const std::vector<bool> members = ensemble_members(runs);
    // Ensemble by ensemble, in the order of their first members: the same rows whether the members
    // were run together or in parts joined by merge.
    std::map<RunSpec, std::vector<std::size_t>> by_ensemble;
    std::vector<RunSpec> order;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        if (!members[i]) continue;
        auto& list = by_ensemble[ensemble_of(runs[i].spec)];
        if (list.empty()) order.push_back(ensemble_of(runs[i].spec));
        list.push_back(i);
    }
    std::string csv;
    for (const auto& ensemble : order)
        for (const std::size_t i : by_ensemble[ensemble])
            for (const auto& [metric, value] : runs[i].metrics)
                csv += csv_record({runs[i].spec.scene, runs[i].spec.scheme, format_number(runs[i].spec.dt),
                                   format_number(member_seed(runs[i].spec)), metric, format_number(value)});
    return csv.empty() ? csv : "scene,scheme,dt,seed,metric,value\n" + csv;
}

}  // namespace rotbench
