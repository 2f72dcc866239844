// `rotbench gate FILE`: the claims and checks of a gate file (docs/gate.md), run by the same
// engine as `run` and judged from the results; exit 1 if any check fails or a check expected
// to fail passes.
#include "harness/analysis/ensemble.hpp"
#include "harness/cli/outputs.hpp"
#include "harness/cli/sweep_command.hpp"
#include "harness/cli/verb.hpp"
#include "harness/exec/parallel.hpp"
#include "harness/gate/compare.hpp"
#include "harness/gate/gate.hpp"
#include "harness/store/journal.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/results_csv.hpp"
#include "reports/gate_report.hpp"

#include <algorithm>
#include <cstdlib>
#include <fcntl.h>
#include <unistd.h>

namespace rotbench {
namespace {

namespace fs = std::filesystem;

// $GITHUB_STEP_SUMMARY belongs to the CI runner and to every step: appended to, never replaced;
// checked before any work (an empty append), so that a wrong one is bad input, not a lost gate.
std::string step_summary() {
    const char* step = std::getenv("GITHUB_STEP_SUMMARY");
    if (!step || !*step) return "";
    try {
        append_to_file(step, "");
    } catch (const OutputError& e) {
        throw InputError(std::string("$GITHUB_STEP_SUMMARY: ") + e.what());
    }
    return step;
}

// --results DIR: the runs a gate made before, each where this gate's plan makes it.
std::vector<RunResult> read_gate_results(const std::string& dir, const GatePlan& plan) {
    std::vector<RunResult> runs = read_results(dir);
    if (runs.size() != plan.runs.size())
        throw InputError("--results " + dir + ": holds " + std::to_string(runs.size()) + " runs, the gate makes " +
                         std::to_string(plan.runs.size()));
    for (std::size_t i = 0; i < runs.size(); ++i)
        if (runs[i].spec.scene != plan.runs[i].scene || runs[i].spec.scheme != plan.runs[i].scheme ||
            runs[i].spec.kind != plan.runs[i].kind || runs[i].spec.dt != plan.runs[i].dt)
            throw InputError("--results " + dir + ": run " + std::to_string(i + 1) + " is not the one this gate makes there");
    return runs;
}

// --baseline DIR: compare's verdicts against the baseline's runs of the schemes this gate ran (a
// scheme left out by --schemes is not missing).
void add_baseline_verdicts(GateResult& result, const std::vector<RunResult>& baseline, const GatePlan& plan, const std::string& where) {
    std::vector<RunResult> selected;
    for (const auto& r : baseline)
        if (std::any_of(plan.runs.begin(), plan.runs.end(), [&](const RunSpec& s) { return s.scheme == r.spec.scheme; }))
            selected.push_back(r);
    const Comparison c = compare_runs(selected, result.runs, {}, where);
    result.verdicts.insert(result.verdicts.end(), c.verdicts.begin(), c.verdicts.end());
    result.warnings.insert(result.warnings.end(), c.notes.begin(), c.notes.end());
}

class GateVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("FILE", file_, "gate file (TOML: [claims], [[check]], [[expected_failure]])")->required();
        command.add_option("--junit", junit_, "write JUnit XML here, and summary.json beside it");
        command.add_option("--summary", summary_, "write the Markdown summary here (also appended to $GITHUB_STEP_SUMMARY)");
        command.add_option("--out", out_, "write gate.csv, summary.json and the runs' store, results.csv and runs.csv here (and the journal)");
        command.add_option("--results", results_, "DIR: judge the runs in DIR (e.g. merged shards) instead of running them");
        command.add_option("--baseline", baseline_, "DIR: also fail on regressions against the runs in DIR (as rotbench compare)");
        command.add_option("--shard", shard_, "K/N: run only the K-th of N slices of the gate's runs (judge the merge with --results)");
        command.add_flag("--quick", quick_, "fit each ladder the file leaves to the scene on its three finest steps (fewer runs, for CI)");
        command.add_option("--schemes", schemes_, "comma list of scheme ids: gate only these (default: all the file names)");
        command.add_option("--jobs", jobs_, "runs in parallel (results do not depend on it)")->check(CLI::Range(1, max_jobs));
        isolation_.add_to(command);
        command.add_flag("--overwrite", overwrite_, "replace the gate's earlier outputs (in --out, and --junit and --summary files)");
    }

    bool resumable() const override { return true; }
    int run(const Invocation& how) override {
        const std::vector<std::string> only = schemes_.empty() ? std::vector<std::string>{} : parse_id_list(schemes_, SchemeRegistry::instance(), "scheme");
        GateFile file = load_gate(file_, only);
        if (!only.empty()) file = only_schemes(std::move(file), only);
        const GatePlan plan = plan_gate(file, quick_);
        const PlanSlice slice = slice_plan(plan.runs, shard_);
        if (slice.shard && out_.empty()) throw InputError("--shard needs --out: a slice's runs are only worth their files");
        if (slice.shard && !results_.empty()) throw InputError("--results judges runs already made: no --shard with it");
        // Every output is checked before the first run: a file in the way fails now, not after the work.
        // --junit's summary.json may be --out's (CI's `--out D --junit D/junit.xml`): the output folder
        // then owns it and writes it once.
        const fs::path junit_json = junit_.empty() ? fs::path() : fs::path(junit_).parent_path() / "summary.json";
        const fs::path out_path = how.resuming ? *how.resuming : fs::path(out_);
        const fs::path out_json = out_path.empty() ? fs::path() : out_path / "summary.json";
        const bool junit_json_in_out = !junit_json.empty() && !out_json.empty() &&
                                       fs::weakly_canonical(junit_json) == fs::weakly_canonical(out_json);
        check_distinct_outputs({{"--junit", junit_}, {"--junit (summary.json beside it)", junit_json}, {"--summary", summary_}});
        check_distinct_outputs({{"--junit", junit_}, {"--summary", summary_}, {"--out (its summary.json)", out_json}});
        const std::string step = step_summary();
        if (!junit_.empty()) {
            check_output_file(junit_, "--junit", overwrite_, junit_signature);
            if (!junit_json_in_out)
                check_output_file(junit_json, "--junit (summary.json beside it)", overwrite_, summary_json_signature);
        }
        if (!summary_.empty()) check_output_file(summary_, "--summary", overwrite_, markdown_signature);
        std::optional<OutputDir> dir;
        if (how.resuming || !out_.empty())
            dir = OutputDir::open(how.resuming ? *how.resuming : fs::path(out_),
                                  {"gate", "gate.csv", slice.shard ? slice_files : std::vector<std::string>{"gate.csv", "summary.json", "runs.jsonl", "schemes.json", "results.csv", "runs.csv"},
                                   overwrite_, how.resuming.has_value()});

        const std::vector<RunResult> baseline = baseline_.empty() ? std::vector<RunResult>{} : collapse_ensembles(read_results(baseline_));
        std::vector<RunResult> runs;
        if (!results_.empty()) {
            runs = read_gate_results(results_, plan);
        } else {
            ExecOptions options{.jobs = jobs_, .timed_alone = true, .verb = "gate"};
            isolation_.apply(options.run);
            Executor executor = make_executor(how, dir ? &*dir : nullptr, options);
            runs = executor.run(slice.runs);
            if (executor.signal()) return executor.interrupted();
            if (slice.shard) {
                write_slice(*dir, slice, runs, how.out);
                Journal::discard(dir->path());
                return 0;
            }
        }

        GateResult result = judge_gate(file, plan, std::move(runs));
        if (!baseline_.empty()) add_baseline_verdicts(result, baseline, plan, baseline_);
        how.out << gate_summary(result);
        if (std::getenv("GITHUB_ACTIONS") && std::string(std::getenv("GITHUB_ACTIONS")) == "true") how.out << gate_annotations(result);
        const std::string json = gate_summary_json(result, file_, provenance());
        if (!junit_.empty()) {
            write_output_file(junit_, gate_junit(result, file_));
            if (!junit_json_in_out) write_output_file(junit_json, json);
        }
        const std::string markdown = gate_markdown(result, "gate", file_);
        if (!summary_.empty()) write_output_file(summary_, markdown);
        if (dir) {
            dir->write("gate.csv", gate_csv(result));
            dir->write("summary.json", json);
            write_run_files(*dir, result.runs, result.runs);  // a gate runs no ensemble
            Journal::discard(dir->path());
        }
        // Last: a runner's file that takes the empty check but not the text loses only itself.
        if (!step.empty()) append_to_file(step, markdown);
        return result.passed() ? 0 : 1;
    }

private:
    std::string file_, junit_, summary_, out_, results_, shard_, baseline_, schemes_;
    IsolationOptions isolation_;
    int jobs_ = core_count();
    bool overwrite_ = false, quick_ = false;
};

const RegisterVerb<GateVerb> gate_verb("gate", "hold every scheme to its claims and the checks of a gate file; exit 1 if any fails");

}  // namespace
}  // namespace rotbench
