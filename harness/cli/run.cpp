// `rotbench run`: the sweep from the options, its outputs, and the journal that lets an
// interrupted run be resumed (harness/store/journal.hpp).
#include "harness/cli/outputs.hpp"
#include "harness/cli/sweep_command.hpp"
#include "harness/cli/verb.hpp"
#include "harness/exec/parallel.hpp"
#include "harness/analysis/sweep_plan.hpp"
#include "harness/cli/config.hpp"
#include "harness/store/journal.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/store/series_csv.hpp"
#include "harness/store/shard.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {
namespace fs = std::filesystem;

namespace {

struct RunOptionsText {
    std::string scenes, schemes, dts, t_end, config, shard, resume, out = "rotbench-out";
    IsolationOptions isolation;
    std::vector<std::string> settings, tolerances;
    int energy_series = 200;
    int jobs = core_count();
    int ensemble = 1;
    bool overwrite = false, quick = false, quiet = false;
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
    spec.ensemble = o.ensemble;
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
    cmd.add_flag("--quick", o.quick, "each scene's short ladder of time steps, and smaller granular scenes (for CI)");
    cmd.add_option("--ensemble", o.ensemble, "K: run each scene with a seed key K times, seeds seed ... seed + K - 1 (means and 95 % intervals)");
    cmd.add_flag("--quiet", o.quiet, "no progress on stderr and no line per failed run");
    cmd.add_option("--shard", o.shard, "K/N: run only the K-th of N deterministic slices (combine with merge)");
    cmd.add_option("--resume", o.resume, "DIR: finish the interrupted run in DIR (with its own options; no other may be given)");
    cmd.add_option("--jobs", o.jobs, "runs in parallel (results do not depend on it)")
        ->capture_default_str()
        ->check(CLI::Range(1, max_jobs));
    o.isolation.add_to(cmd);
    add_tolerance_option(cmd, o.tolerances);
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
                                 (std::filesystem::path(dir) / "partial" / "runs.jsonl").string());
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
    std::vector<std::string> skipped;
    const PlanSlice slice = slice_plan(plan_sweep(sweep_spec(o), &skipped), o.shard);  // every input checked before anything runs
    parse_tolerances(o.tolerances);
    const OutputDir dir = OutputDir::open(how.resuming ? *how.resuming : fs::path(o.out),
                                          {"run", "results.csv", slice.shard ? slice_files : run_files, o.overwrite,
                                           how.resuming.has_value()});
    const AnalysisOptions analysis = analysis_options(o.tolerances, dir.path(), dir.path());  // a stability study already in --out
    ExecOptions options{.jobs = o.jobs, .quiet = o.quiet};
    options.run.series_samples = o.energy_series;
    o.isolation.apply(options.run);
    for (const auto& why : skipped) how.out << "skipped: " << why << "\n";
    Executor executor = make_executor(how, &dir, options);
    const std::vector<RunResult> results = executor.run(slice.runs);
    if (executor.signal()) return executor.interrupted();
    if (!slice.shard) write_outputs(dir, results, how.command_line, analysis, how.out);
    else write_slice(dir, slice, results, how.out);  // no orders or report: they need every run
    Journal::discard(dir.path());
    return 0;
}

class RunVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command_ = &command;
        add_run_options(command, options_);
    }
    bool defers_plugins() const override { return !options_.resume.empty(); }
    bool resumable() const override { return true; }
    int run(const Invocation& how) override {
        if (!options_.resume.empty()) {
            if (how.resuming)
                throw InputError("--resume: " + (*how.resuming / "partial" / "runs.jsonl").string() + " holds --resume itself");
            return resume(*command_, options_.resume, how.out, how.err);
        }
        return run_sweep_command(options_, how);
    }

private:
    RunOptionsText options_;
    CLI::App* command_ = nullptr;
};

const RegisterVerb<RunVerb> run_verb("run", "run schemes on scenes and write results.csv and report.md");

}  // namespace
}  // namespace rotbench
