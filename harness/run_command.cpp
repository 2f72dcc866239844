#include "harness/run_command.hpp"

#include "harness/config.hpp"
#include "harness/interrupt.hpp"
#include "harness/journal.hpp"
#include "harness/parallel.hpp"
#include "harness/parse.hpp"
#include "harness/shard.hpp"
#include "harness/sweep.hpp"
#include "reports/energy_series.hpp"
#include "reports/markdown_report.hpp"
#include "reports/orders.hpp"
#include "reports/output_files.hpp"
#include "reports/results_csv.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

// The sweep the options describe: the config file first, the command line over it.
SweepSpec sweep_spec(const RunOptionsText& o) {
    SweepSpec spec = o.config.empty() ? SweepSpec{} : load_config(o.config);
    if (!o.scenes.empty()) spec.scenes = parse_id_list(o.scenes, SceneRegistry::instance(), "scene");
    if (!o.schemes.empty()) spec.schemes = parse_id_list(o.schemes, SchemeRegistry::instance(), "scheme");
    if (!o.dts.empty()) spec.dts = parse_positive_list(o.dts, "--dt");
    if (!o.t_end.empty()) spec.t_end = parse_positive(o.t_end, "--t-end");
    for (const auto& s : o.settings) add_setting(spec, s);
    spec.quick = o.quick;
    return spec;
}

}  // namespace

int RunOptionsText::default_jobs() { return core_count(); }

void add_run_options(CLI::App& cmd, RunOptionsText& o) {
    cmd.add_option("--scenes", o.scenes, "comma list of scene ids (default: all)");
    cmd.add_option("--schemes", o.schemes, "comma list of scheme ids (default: all)");
    cmd.add_option("--dt", o.dts, "comma list of time steps in s (default: each scene's ladder)");
    cmd.add_option("--t-end", o.t_end, "duration in s (default: each scene's)");
    cmd.add_option("--out", o.out, "output directory")->capture_default_str();
    cmd.add_flag("--overwrite", o.overwrite, "replace results (or an interrupted run) already in --out");
    cmd.add_option("--set", o.settings, "scene parameter, SCENE.KEY=VALUE (repeatable; VALUE may be a comma list)");
    cmd.add_option("--config", o.config, "TOML file with [run] selections and [SCENE] parameters");
    cmd.add_flag("--quick", o.quick, "each scene's short ladder of time steps (for CI)");
    cmd.add_option("--shard", o.shard, "K/N: run only the K-th of N deterministic slices (combine with merge)");
    cmd.add_option("--resume", o.resume, "DIR: finish the interrupted run in DIR (with its own options; no other may be given)");
    cmd.add_option("--jobs", o.jobs, "runs in parallel (results do not depend on it)")
        ->capture_default_str()
        ->check(CLI::Range(1, max_jobs));
    cmd.add_option("--energy-series", o.energy_series, "energy samples per run in scenes that plot it (0: none)")
        ->capture_default_str()
        ->check(CLI::Range(0, max_series_samples));
}

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

void write_outputs(const fs::path& dir, const std::vector<RunResult>& results, const std::string& command_line,
                   std::ostream& out) {
    write_file_atomically(dir / "results.csv", results_csv(results));
    write_file_atomically(dir / "runs.csv", runs_csv(results));
    const auto orders = observed_orders(results);
    write_file_atomically(dir / "orders.csv", orders_csv(orders));
    write_file_atomically(dir / "local_orders.csv", local_orders_csv(orders));
    write_file_atomically(dir / "report.md", markdown_report(results, command_line, dir));
    out << fmt::format("wrote {} and {}\n", (dir / "results.csv").string(), (dir / "report.md").string());
}

int run_command(const RunOptionsText& o, const std::vector<std::string>& arguments, const std::string& command_line,
                std::ostream& out, std::ostream& err, const std::optional<fs::path>& resuming) {
    auto plan = plan_sweep(sweep_spec(o));  // every input checked before anything runs
    const std::size_t plan_size = plan.size();
    const std::string id = plan_id(plan);
    std::vector<std::size_t> indices;
    const Shard shard = o.shard.empty() ? Shard{} : parse_shard(o.shard);
    if (!o.shard.empty()) {
        // An empty slice would leave merge nothing to recognise it by.
        if (static_cast<std::size_t>(shard.count) > plan_size)
            throw InputError(fmt::format("--shard {}: the sweep has only {} run(s), so at most {} shard(s)", o.shard, plan_size, plan_size));
        indices = shard_indices(plan_size, shard);
        std::vector<RunSpec> slice;
        for (std::size_t i : indices) slice.push_back(plan[i]);
        plan = std::move(slice);
    }
    const fs::path dir = resuming ? *resuming : prepare_output(o.out, "results.csv", o.overwrite);
    const std::string journal_id = fmt::format("{}/{}/{}", id, shard.index, shard.count);
    const Journal journal =
        resuming ? Journal::reopen(dir, journal_id, plan.size()) : Journal::start(dir, arguments, journal_id, plan.size());

    std::vector<RunSpec> todo;
    std::vector<std::size_t> todo_index;
    {
        const auto finished = journal.finished();
        for (std::size_t i = 0; i < plan.size(); ++i)
            if (!finished.count(i)) todo.push_back(plan[i]), todo_index.push_back(i);
        if (resuming) out << fmt::format("resuming: {} of {} runs were finished\n", finished.size(), plan.size());
    }
    std::size_t kept = plan.size() - todo.size();  // runs in the journal
    RunOptions options;
    options.series_samples = o.energy_series;
    {
        const InterruptGuard guard;
        run_sweep(
            todo, options,
            [&](std::size_t i, const RunResult& r) {
                journal.record(todo_index[i], r);
                ++kept;
                out << fmt::format("{:<16} {:<16} dt={:<10g} {}\n", r.spec.scene, r.spec.scheme, r.spec.dt,
                                   r.failure.empty() ? "ok" : "FAILED: " + r.failure);
            },
            o.jobs);
        if (const int signal = interrupt_signal()) {
            err << fmt::format("rotbench: interrupted by signal {}: {} of {} runs are kept in {}; rotbench run --resume {} "
                               "finishes the sweep\n",
                               signal, kept, plan.size(), (dir / "partial").string(), dir.string());
            return 128 + signal;
        }
    }
    // The outputs come from the journal, as a resumed run's do: the two are the same files.
    std::vector<RunResult> results;
    for (auto& [index, r] : journal.finished()) results.push_back(std::move(r));
    if (o.shard.empty()) {
        write_outputs(dir, results, command_line, out);
    } else {  // a slice: the runs and series for `merge`, no orders or report (they need every run)
        write_file_atomically(dir / "results.csv", results_csv(results));
        write_file_atomically(dir / "runs.csv", runs_csv(results));
        write_energy_series(results, dir);
        write_file_atomically(dir / "shard.csv", shard_csv(id, shard.index, shard.count, results, indices, plan_size));
        out << fmt::format("wrote shard {}/{} ({} of {} runs) to {}; combine the shards with rotbench merge\n", shard.index,
                           shard.count, results.size(), plan_size, dir.string());
    }
    journal.remove();
    return 0;
}

}  // namespace rotbench
