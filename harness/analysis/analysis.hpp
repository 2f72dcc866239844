// What a set of runs says, computed once: the orders, the answer, each scheme's verdicts and
// the recommendation, the clients against their counterparts, the seed's Table 1; with the
// stability study and the benchmarks' cost tables measured beside it. The data
// files are written from it (export_analysis) and the report only formats it (reports/).
#pragma once

#include "harness/analysis/answer.hpp"
#include "harness/analysis/cost_tables.hpp"
#include "harness/analysis/expected_orders.hpp"
#include "harness/analysis/orders.hpp"
#include "harness/analysis/result_set.hpp"
#include "harness/analysis/scheme_verdicts.hpp"
#include "harness/analysis/seed_table1.hpp"
#include "harness/analysis/stability_study.hpp"
#include "harness/store/output_dir.hpp"

#include <optional>
#include <string>
#include <vector>

namespace rotbench {

struct AnalysisOptions {
    std::vector<double> tolerances = default_tolerances;  // relative angular-velocity errors
    std::vector<StabilityRow> stability;                  // the stability study's rows; empty without one
    std::optional<CostTable> cost;                        // benchmarks/cost.py's table, if measured
    std::vector<GranularSpeedRow> granular_speed;         // benchmarks/granular_speed.py's, if measured
};

struct Analysis {
    ResultSet set;
    std::vector<double> tolerances;
    std::vector<StabilityRow> stability;
    std::vector<ExpectedOrder> expected;  // what each scheme of the set claims
    std::vector<OrderRow> orders;
    std::vector<LargestDt> answers;
    std::vector<SchemeVerdict> verdicts;
    SchemeChoice recommendation;
    std::vector<CounterpartVerdict> counterparts;
    std::vector<Table1Comparison> table1;
    std::optional<CostTable> cost;
    std::vector<GranularSpeedRow> granular_speed;
};

Analysis analyse(ResultSet set, AnalysisOptions options);

// The files export_analysis writes, besides each run's series, snapshots and walls (series/,
// snapshots/, walls/).
inline const std::vector<std::string> analysis_files = {"orders.csv", "local_orders.csv", "answer.csv"};
void export_analysis(const OutputDir& dir, const Analysis& analysis);

}  // namespace rotbench
