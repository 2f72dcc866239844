// `rotbench stability`: the measured stability limits, those of the eigenvalues of each
// scheme's step map, and Peng et al.'s predictions, on the contact pairs and fast_spin.
#include "harness/analysis/result_set.hpp"
#include "harness/analysis/stability_study.hpp"
#include "harness/cli/outputs.hpp"
#include "harness/cli/sweep_command.hpp"
#include "harness/cli/verb.hpp"
#include "harness/exec/machine.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/results_csv.hpp"
#include "harness/analysis/stability_csv.hpp"
#include "harness/scenes/scene.hpp"
#include "reports/stability_report.hpp"
#include "schemes/scheme.hpp"

namespace rotbench {
namespace {

namespace fs = std::filesystem;

class StabilityVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("--scenes", scenes_, "contact scenes")->capture_default_str();
        command.add_option("--schemes", schemes_, "comma list of scheme ids (default: all)");
        command.add_option("--zeta", zetas_, "damping ratios (contact scenes)")->capture_default_str();
        command.add_option("--omega-max", omegas_, "spin rates, rad/s (fast_spin)")->capture_default_str();
        command.add_option("--out", out_, "output directory")->capture_default_str();
        command.add_option("--jobs", jobs_, "cases in parallel")->check(CLI::Range(1, max_jobs));
        command.add_flag("--overwrite", overwrite_, "replace results already in --out");
        command.add_flag("--quiet", quiet_, "no progress on stderr");
        isolation_.add_to(command, "600 s for a search");
    }
    bool resumable() const override { return true; }
    int run(const Invocation& how) override {
        const auto scenes = parse_id_list(scenes_, SceneRegistry::instance(), "scene");
        const auto schemes = schemes_.empty() ? SchemeRegistry::instance().ids()
                                              : parse_id_list(schemes_, SchemeRegistry::instance(), "scheme");
        const auto zetas = parse_nonnegative_list(zetas_, "--zeta");
        const auto omegas = parse_positive_list(omegas_, "--omega-max");
        std::vector<std::string> skipped;
        const std::vector<RunSpec> plan = stability_plan(scenes, schemes, zetas, omegas, &skipped);  // every input checked first
        const OutputDir dir = OutputDir::open(how.resuming ? *how.resuming : fs::path(out_),
                                              {"stability", "stability.csv",
                                               {stability_store, "stability.csv", "stability_spin.csv", "stability.md"},
                                               overwrite_, how.resuming.has_value()});
        for (const auto& why : skipped) how.out << "skipped: " << why << "\n";
        ExecOptions options{.jobs = jobs_, .quiet = quiet_, .verb = "stability"};
        isolation_.apply(options.run);
        std::vector<RunResult> runs;
        {
            Executor executor = make_executor(how, &dir, options);
            runs = executor.run(plan);
            if (executor.signal()) return executor.interrupted();
        }
        const auto [rows, curves] = stability_study(runs, stability_store);
        dir.write(stability_store, run_store(runs));
        dir.write("stability.csv", stability_csv(rows));
        dir.write("stability_spin.csv", stability_spin_csv(rows));
        ResultSet families;  // the schemes' families, for the plots' panels
        for (const auto& id : schemes) families.schemes[id] = scheme_info(id);
        const std::string section = stability_section(rows, families, dir);
        dir.write("stability.md", "# rotbench stability\n\nCommand: `" + how.command_line + "`\n\n" + section +
                                      spectral_radius_plots(curves, families, dir));
        Journal::discard(dir.path());
        how.out << "wrote " << (dir.path() / "stability.csv").string() << " and " << (dir.path() / "stability.md").string() << "\n";
        return 0;
    }

private:
    std::string scenes_ = "sphere_pair,ellipsoid_pair,fast_spin", schemes_, zetas_ = "0,0.1,0.3,0.5", omegas_ = "10,100,1000",
                out_ = "rotbench-stability";
    IsolationOptions isolation_;
    bool overwrite_ = false, quiet_ = false;
    int jobs_ = core_count();
};

const RegisterVerb<StabilityVerb> stability_verb("stability", "stability limits: measured, from eigenvalues, and Peng et al.'s");

}  // namespace
}  // namespace rotbench
