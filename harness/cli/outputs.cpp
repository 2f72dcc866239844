#include "harness/cli/outputs.hpp"

#include "harness/analysis/orders.hpp"
#include "harness/analysis/result_set.hpp"
#include "harness/engine/parallel.hpp"
#include "harness/io/journal.hpp"
#include "harness/io/orders_csv.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/results_csv.hpp"
#include "reports/markdown_report.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace fs = std::filesystem;

fs::path prepare_output(const std::string& dir, const std::string& marker, bool overwrite) {
    const fs::path path(dir);
    if (fs::exists(path / marker) && !overwrite)
        throw InputError("--out " + dir + " already holds " + marker + "; pass --overwrite or choose another directory");
    if (Journal::exists(path) && !overwrite)
        throw InputError("--out " + dir + " holds an interrupted run; rotbench run --resume " + dir +
                         " finishes it, --overwrite starts again");
    std::error_code ec;
    fs::create_directories(path, ec);
    if (ec || !fs::is_directory(path)) throw InputError("--out " + dir + ": cannot create the directory");
    const fs::path probe = path / ".rotbench-write-probe";
    try {
        write_file_atomically(probe, "");
    } catch (const InputError&) {
        throw InputError("--out " + dir + ": the directory is not writable");
    }
    fs::remove(probe, ec);
    return path;
}

Executor all_cores() {
    return [](std::size_t count, const std::function<void(std::size_t)>& work) { parallel_for(count, core_count(), work); };
}

void write_outputs(const fs::path& dir, const std::vector<RunResult>& results, const std::string& command_line,
                   std::ostream& out) {
    write_file_atomically(dir / "results.csv", results_csv(results));
    write_file_atomically(dir / "runs.csv", runs_csv(results));
    const auto orders = observed_orders(results);
    write_file_atomically(dir / "orders.csv", orders_csv(orders));
    write_file_atomically(dir / "local_orders.csv", local_orders_csv(orders));
    write_file_atomically(dir / "report.md", markdown_report(describe(results), command_line, dir, all_cores()));
    out << fmt::format("wrote {} and {}\n", (dir / "results.csv").string(), (dir / "report.md").string());
}

}  // namespace rotbench
