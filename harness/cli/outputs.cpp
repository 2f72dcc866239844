#include "harness/cli/outputs.hpp"

#include "harness/analysis/ensemble.hpp"
#include "harness/analysis/analysis.hpp"
#include "harness/analysis/result_set.hpp"
#include "harness/exec/parallel.hpp"
#include "harness/analysis/ensemble_csv.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/analysis/stability_study.hpp"
#include "reports/markdown_report.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {
namespace fs = std::filesystem;

ParallelWork all_cores() {
    return [](std::size_t count, const std::function<void(std::size_t)>& work) { parallel_for(count, core_count(), work); };
}

void add_tolerance_option(CLI::App& command, std::vector<std::string>& texts) {
    command.add_option("--tolerance", texts, "relative angular-velocity error the report answers for (repeatable; default 1e-3 and 1e-6)");
}

std::vector<double> parse_tolerances(const std::vector<std::string>& texts) {
    if (texts.empty()) return default_tolerances;
    std::vector<double> out;
    for (const auto& t : texts)
        for (double v : parse_positive_list(t, "--tolerance")) {
            if (!(v < 1.0)) throw InputError(fmt::format("--tolerance: {} is not below 1 (a relative error)", t));
            if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
        }
    std::sort(out.rbegin(), out.rend());  // loosest first
    return out;
}

AnalysisOptions analysis_options(const std::vector<std::string>& tolerances, const fs::path& run_dir, const fs::path& stability_dir) {
    AnalysisOptions options;
    options.tolerances = parse_tolerances(tolerances);
    options.cost = read_cost_table(run_dir);
    options.granular_speed = read_granular_speed(run_dir);
    if (fs::exists(stability_dir / stability_store))
        options.stability = stability_study(read_results(stability_dir, stability_store), (stability_dir / stability_store).string()).rows;
    return options;
}

void write_outputs(const OutputDir& dir, const std::vector<RunResult>& all_runs, const std::string& command_line,
                   const AnalysisOptions& options, std::ostream& out, const SchemeInfos& recorded) {
    // An ensemble's members are kept in the store and ensemble.csv; the tables hold their means and intervals.
    if (const std::string members = ensemble_csv(all_runs); !members.empty()) dir.write("ensemble.csv", members);
    const std::vector<RunResult> results = collapse_ensembles(all_runs);
    write_run_files(dir, all_runs, results, recorded);
    const Analysis analysis = analyse(describe(results, recorded), options);
    export_analysis(dir, analysis);
    dir.write("report.md", markdown_report(analysis, command_line, dir, all_cores()));
    out << fmt::format("wrote {} and {}\n", (dir.path() / "results.csv").string(), (dir.path() / "report.md").string());
}

}  // namespace rotbench
