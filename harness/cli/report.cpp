// `rotbench report DIR`: report.md and its plots again, from the run store a run left in DIR.
#include "harness/analysis/analysis.hpp"
#include "harness/analysis/ensemble.hpp"
#include "harness/analysis/stability_study.hpp"
#include "harness/cli/outputs.hpp"
#include "harness/cli/verb.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/results_csv.hpp"
#include "reports/markdown_report.hpp"

namespace rotbench {
namespace {

class ReportVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("DIR", dir_, "a directory written by rotbench run")->required();
        command.add_option("--out", out_, "write report.md and its plots here instead (default: DIR)");
        command.add_flag("--overwrite", overwrite_, "write into an --out that holds files rotbench did not write (beside them)");
        command.add_option("--stability", stability_, "the stability study to include (a directory rotbench stability wrote; default: DIR)");
        add_tolerance_option(command, tolerances_);
    }
    int run(const Invocation& how) override {
        const AnalysisOptions options = analysis_options(tolerances_, dir_, stability_.empty() ? dir_ : stability_);
        if (!stability_.empty() && options.stability.empty())
            throw InputError("--stability " + stability_ + ": no " + stability_store + " there (rotbench stability --out writes one)");
        const Analysis analysis = analyse(describe(collapse_ensembles(read_results(dir_)), read_schemes(dir_)), options);
        std::vector<std::string> written = analysis_files;
        written.push_back("report.md");
        const OutputDir out = OutputDir::open(out_.empty() ? dir_ : out_, {"run", "", written, overwrite_});
        if (!out_.empty() && !std::filesystem::equivalent(out_, dir_))
            for (const char* table : {"cost.csv", "granular_speed.csv"})  // the cost tables go with the report
                if (std::filesystem::exists(std::filesystem::path(dir_) / table))
                    out.write(table, read_input_file(std::filesystem::path(dir_) / table, "cannot read"));
        export_analysis(out, analysis);
        out.write("report.md", markdown_report(analysis, how.command_line, out, all_cores()));
        how.out << "wrote " << (out.path() / "report.md").string() << "\n";
        return 0;
    }

private:
    std::string dir_, out_, stability_;
    std::vector<std::string> tolerances_;
    bool overwrite_ = false;
};

const RegisterVerb<ReportVerb> report_verb("report", "re-render report.md and its plots from the run store in DIR");

}  // namespace
}  // namespace rotbench
