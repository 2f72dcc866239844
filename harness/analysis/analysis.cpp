#include "harness/analysis/analysis.hpp"

#include "harness/analysis/orders_csv.hpp"
#include "harness/store/series_csv.hpp"

namespace rotbench {

Analysis analyse(ResultSet set, AnalysisOptions options) {
    Analysis a;
    a.set = std::move(set);
    a.tolerances = std::move(options.tolerances);
    a.stability = std::move(options.stability);
    a.cost = std::move(options.cost);
    a.granular_speed = std::move(options.granular_speed);
    for (const auto& [id, info] : a.set.schemes) add_expected_orders(id, info.claims, a.expected);
    a.orders = observed_orders(a.set.runs);
    a.answers = largest_dts(a.set, a.orders, a.tolerances, a.stability);
    a.verdicts = scheme_verdicts(a.set, a.orders, a.stability);
    a.recommendation = recommend(a.verdicts, a.stability);
    a.counterparts = counterpart_verdicts(a.set);
    a.table1 = compare_table1(a.set.runs);
    return a;
}

void export_analysis(const OutputDir& dir, const Analysis& a) {
    dir.write("orders.csv", orders_csv(a.orders));
    dir.write("local_orders.csv", local_orders_csv(a.orders));
    dir.write("answer.csv", answer_csv(a.answers));
    write_run_series(a.set.runs, dir);  // what the report's plots draw: series/, snapshots/, walls/
}

}  // namespace rotbench
