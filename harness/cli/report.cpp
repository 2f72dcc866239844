// `rotbench report DIR`: report.md and its plots again, from the CSVs a run left in DIR.
#include "harness/analysis/result_set.hpp"
#include "harness/cli/outputs.hpp"
#include "harness/cli/verb.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/results_csv.hpp"
#include "reports/markdown_report.hpp"

namespace rotbench {
namespace {

class ReportVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("DIR", dir_, "a directory written by rotbench run")->required();
    }
    int run(const Invocation& how) override {
        const std::filesystem::path dir(dir_);
        const ResultSet set = describe(read_results(dir));
        write_file_atomically(dir / "report.md", markdown_report(set, how.command_line, dir, all_cores()));
        how.out << "wrote " << (dir / "report.md").string() << "\n";
        return 0;
    }

private:
    std::string dir_;
};

const RegisterVerb<ReportVerb> registration("report", "re-render report.md and its plots from the CSVs in DIR");

}  // namespace
}  // namespace rotbench
