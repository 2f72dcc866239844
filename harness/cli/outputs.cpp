#include "harness/cli/outputs.hpp"

#include "harness/analysis/orders.hpp"
#include "harness/analysis/result_set.hpp"
#include "harness/engine/parallel.hpp"
#include "harness/io/orders_csv.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/results_csv.hpp"
#include "reports/markdown_report.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace fs = std::filesystem;

Executor all_cores() {
    return [](std::size_t count, const std::function<void(std::size_t)>& work) { parallel_for(count, core_count(), work); };
}

void write_outputs(const OutputDir& dir, const std::vector<RunResult>& results, const std::string& command_line,
                   std::ostream& out) {
    dir.write("results.csv", results_csv(results));
    dir.write("runs.csv", runs_csv(results));
    const auto orders = observed_orders(results);
    dir.write("orders.csv", orders_csv(orders));
    dir.write("local_orders.csv", local_orders_csv(orders));
    dir.write("report.md", markdown_report(describe(results), command_line, dir, all_cores()));
    out << fmt::format("wrote {} and {}\n", (dir.path() / "results.csv").string(), (dir.path() / "report.md").string());
}

}  // namespace rotbench
