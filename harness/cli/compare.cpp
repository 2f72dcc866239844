// `rotbench compare BASE NEW`: every metric of the runs found in both directories, and the
// regressions among them (harness/gate/compare.hpp); exit 1 if there is one.
#include "harness/analysis/ensemble.hpp"
#include "harness/cli/outputs.hpp"
#include "harness/cli/verb.hpp"
#include "harness/gate/compare.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/store/scheme_record.hpp"
#include "reports/gate_report.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace {

namespace fs = std::filesystem;

// A client whose program, file or program files differ between the two folders (schemes.json):
// a change of results may be the code's, not rotbench's, and the reader is told so first.
std::vector<std::string> client_changes(const SchemeInfos& base, const SchemeInfos& now) {
    std::vector<std::string> out;
    for (const auto& [id, b] : base) {
        const auto n = now.find(id);
        if (!b.client || n == now.end() || !n->second.client) continue;
        if (b.source != n->second.source) out.push_back(fmt::format("client {}: its program changed: {} -> {}", id, b.source, n->second.source));
        else if (b.program_hash != n->second.program_hash)
            out.push_back(fmt::format("client {}: its program's files changed (FNV-1a {} -> {})", id, b.program_hash, n->second.program_hash));
        if (b.client_hash != n->second.client_hash)
            out.push_back(fmt::format("client {}: its client file changed (FNV-1a {} -> {})", id, b.client_hash, n->second.client_hash));
    }
    return out;
}

class CompareVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("BASE", base_, "the baseline: a directory written by run, gate --out or merge")->required();
        command.add_option("NEW", now_, "the directory to compare with it")->required();
        command.add_option("--out", out_, "write compare.csv (every change) and summary.json here");
        command.add_option("--junit", junit_, "write JUnit XML here (a test case per check of each scene and scheme)");
        command.add_option("--summary", summary_, "write the Markdown summary here");
        command.add_option("--error-tolerance", error_, "relative error increase that is a regression")->capture_default_str();
        command.add_option("--order-tolerance", order_, "observed-order drop that is a regression")->capture_default_str();
        command.add_option("--cost-tolerance", cost_, "relative cost increase that is a regression, when significant")->capture_default_str();
        command.add_flag("--overwrite", overwrite_, "replace compare's earlier outputs (in --out, and --junit and --summary files)");
    }
    int run(const Invocation& how) override {
        BaselineTolerances tolerances;
        tolerances.error = parse_positive(error_, "--error-tolerance");
        tolerances.order = parse_positive(order_, "--order-tolerance");
        tolerances.cost = parse_positive(cost_, "--cost-tolerance");
        const auto base = collapse_ensembles(read_results(base_)), now = collapse_ensembles(read_results(now_));
        check_distinct_outputs({{"--junit", junit_},
                                {"--summary", summary_},
                                {"--out (its summary.json)", out_.empty() ? std::filesystem::path() : std::filesystem::path(out_) / "summary.json"},
                                {"--out (its compare.csv)", out_.empty() ? std::filesystem::path() : std::filesystem::path(out_) / "compare.csv"}});
        if (!junit_.empty()) check_output_file(junit_, "--junit", overwrite_, junit_signature);
        if (!summary_.empty()) check_output_file(summary_, "--summary", overwrite_, markdown_signature);
        std::optional<OutputDir> dir;
        if (!out_.empty()) dir = OutputDir::open(out_, {"compare", "compare.csv", {"compare.csv", "summary.json"}, overwrite_});
        const Comparison c = compare_runs(base, now, tolerances, base_);
        GateResult result;
        result.verdicts = c.verdicts;
        result.warnings = client_changes(read_schemes(base_), read_schemes(now_));
        result.warnings.insert(result.warnings.end(), c.notes.begin(), c.notes.end());
        how.out << gate_summary(result);
        if (!junit_.empty()) write_output_file(junit_, gate_junit(result, base_));
        if (!summary_.empty()) write_output_file(summary_, gate_markdown(result, "compare", base_ + " -> " + now_));
        if (dir) {
            dir->write("compare.csv", compare_csv(c));
            dir->write("summary.json", gate_summary_json(result, base_ + " -> " + now_, provenance()));
        }
        return result.passed() ? 0 : 1;
    }

private:
    std::string base_, now_, out_, junit_, summary_, error_ = fmt::format("{:g}", BaselineTolerances{}.error),
                order_ = fmt::format("{:g}", BaselineTolerances{}.order), cost_ = fmt::format("{:g}", BaselineTolerances{}.cost);
    bool overwrite_ = false;
};

const RegisterVerb<CompareVerb> compare_verb("compare", "regressions of NEW against BASE: accuracy, orders, stability, cost");

}  // namespace
}  // namespace rotbench
