// `rotbench run`: the sweep from the options, its outputs, and the journal that lets an
// interrupted run be resumed (harness/io/journal.hpp).
#include "harness/cli/outputs.hpp"
#include "harness/cli/verb.hpp"
#include "harness/engine/interrupt.hpp"
#include "harness/engine/parallel.hpp"
#include "harness/engine/sweep.hpp"
#include "harness/io/config.hpp"
#include "harness/io/journal.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/parse.hpp"
#include "harness/io/results_csv.hpp"
#include "harness/io/series_csv.hpp"
#include "harness/io/shard.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

struct RunOptionsText {
    std::string scenes, schemes, dts, t_end, config, shard, resume, out = "rotbench-out";
    std::vector<std::string> settings;
    int energy_series = 200;
    int jobs = core_count();
    bool overwrite = false, quick = false;
};

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

// The interrupted run's own arguments, run again from the directory it was started in
// (relative paths in them stay right); its journal holds the finished runs.
int resume(const CLI::App& run_cmd, const std::string& dir, std::ostream& out, std::ostream& err) {
    for (const auto* command : {run_cmd.get_parent(), &run_cmd})
        for (const auto* option : command->get_options())
            if (option->count() > 0 && option->get_name() != "--resume")
                throw InputError(option->get_name() + ": --resume DIR takes no other option; the sweep's are read from " +
                                 (std::filesystem::path(dir) / "partial" / "command").string());
    const auto absolute = std::filesystem::absolute(dir);
    const auto arguments = Journal::arguments(absolute);
    const auto here = std::filesystem::current_path();
    std::filesystem::current_path(Journal::working_directory(absolute));
    struct GoBack {
        std::filesystem::path to;
        ~GoBack() {
            std::error_code ec;
            std::filesystem::current_path(to, ec);
        }
    } go_back{here};
    return run_cli_arguments(arguments, out, err, absolute);
}

int run_sweep_command(const RunOptionsText& o, const Invocation& how) {
    const std::vector<std::string>& arguments = how.arguments;
    const std::string& command_line = how.command_line;
    std::ostream& out = how.out;
    std::ostream& err = how.err;
    const std::optional<fs::path>& resuming = how.resuming;
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

class RunVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command_ = &command;
        add_run_options(command, options_);
    }
    bool defers_plugins() const override { return !options_.resume.empty(); }
    int run(const Invocation& how) override {
        if (!options_.resume.empty()) {
            if (how.resuming)
                throw InputError("--resume: " + (*how.resuming / "partial" / "command").string() + " holds --resume itself");
            return resume(*command_, options_.resume, how.out, how.err);
        }
        return run_sweep_command(options_, how);
    }

private:
    RunOptionsText options_;
    CLI::App* command_ = nullptr;
};

const RegisterVerb<RunVerb> registration("run", "run schemes on scenes and write results.csv and report.md");

}  // namespace
}  // namespace rotbench
