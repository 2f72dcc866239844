// `rotbench merge DIR... --out OUT`: the outputs of the unsharded run from its N slices, or of
// whole runs joined (an ensemble grown in parts).
#include "harness/cli/outputs.hpp"
#include "harness/cli/verb.hpp"
#include "harness/store/shard.hpp"
#include "harness/store/scheme_record.hpp"

namespace rotbench {
namespace {

class MergeVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("DIRS", dirs_, "the shard directories, one per K; or whole run directories to join")->required();
        command.add_option("--out", out_, "output directory")->required();
        command.add_flag("--overwrite", overwrite_, "replace results already in --out");
        add_tolerance_option(command, tolerances_);
    }
    int run(const Invocation& how) override {
        const std::vector<std::filesystem::path> dirs(dirs_.begin(), dirs_.end());
        parse_tolerances(tolerances_);
        const auto results = merge_runs(dirs);
        const OutputDir out = OutputDir::open(out_, {"run", "results.csv", run_files, overwrite_});
        SchemeInfos recorded;  // what each slice ran: merge needs no --plugin to describe a plug-in's runs
        for (const auto& dir : dirs) recorded.merge(read_schemes(dir));
        write_outputs(out, results, how.command_line, analysis_options(tolerances_, out.path(), out.path()), how.out, recorded);
        return 0;
    }

private:
    std::vector<std::string> dirs_, tolerances_;
    std::string out_;
    bool overwrite_ = false;
};

const RegisterVerb<MergeVerb> merge_verb("merge", "combine the outputs of run --shard K/N, or of whole runs, into one run's outputs");

}  // namespace
}  // namespace rotbench
