// `rotbench gate FILE`: the checks of a gate file; exit 1 if any fails (harness/gate/gate.hpp).
#include "harness/cli/outputs.hpp"
#include "harness/cli/verb.hpp"
#include "harness/engine/parallel.hpp"
#include "harness/gate/gate.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/results_csv.hpp"
#include "reports/gate_report.hpp"

#include <algorithm>

namespace rotbench {
namespace {

class GateVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("FILE", file_, "gate file (TOML, [[check]] tables)")->required();
        command.add_option("--junit", junit_, "write JUnit XML here (one test case per check and scheme)");
        command.add_option("--out", out_, "also write gate.csv and results.csv of the runs here");
        command.add_option("--jobs", jobs_, "runs in parallel (results do not depend on it)")->check(CLI::Range(1, max_jobs));
        command.add_flag("--overwrite", overwrite_, "replace a gate.csv already in --out");
    }
    int run(const Invocation& how) override {
        const auto checks = load_gate(file_);
        std::filesystem::path dir;
        if (!out_.empty()) dir = prepare_output(out_, "gate.csv", overwrite_);
        if (!junit_.empty()) {
            const std::filesystem::path parent = std::filesystem::path(junit_).parent_path();
            if (!parent.empty() && !std::filesystem::is_directory(parent))
                throw InputError("--junit " + junit_ + ": the directory " + parent.string() + " does not exist");
        }
        const GateResult result = run_gate(checks, jobs_);
        how.out << gate_summary(checks, result);
        if (!junit_.empty()) write_file_atomically(junit_, gate_junit(checks, result));
        if (!dir.empty()) {
            write_file_atomically(dir / "gate.csv", gate_csv(checks, result));
            write_file_atomically(dir / "results.csv", results_csv(result.runs));
        }
        const bool passed = std::all_of(result.outcomes.begin(), result.outcomes.end(), [](const GateOutcome& g) { return g.passed; });
        return passed ? 0 : 1;
    }

private:
    std::string file_, junit_, out_;
    int jobs_ = core_count();
    bool overwrite_ = false;
};

const RegisterVerb<GateVerb> registration("gate", "run the checks of a gate file; exit 1 if any fails");

}  // namespace
}  // namespace rotbench
