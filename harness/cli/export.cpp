// `rotbench reference` and `rotbench trajectory`: a scene's reference trajectory, or one
// scheme's run on it, as CSV (harness/exec/export.hpp gives the columns).
#include "harness/cli/verb.hpp"
#include "harness/exec/executor.hpp"
#include "harness/exec/export.hpp"
#include "harness/analysis/sweep_plan.hpp"
#include "harness/cli/config.hpp"
#include "harness/cli/outputs.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/output_files.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/series_csv.hpp"
#include "schemes/scheme.hpp"

#include <filesystem>

namespace rotbench {
namespace {

struct ExportOptions {
    std::string scene, scheme, dt, t_end, out;
    bool overwrite = false;
    std::vector<std::string> settings;
    int samples = 1000;

    void add_to(CLI::App& cmd) {
        cmd.add_option("--scene", scene, "scene id")->required();
        cmd.add_option("--t-end", t_end, "duration in s (default: the scene's)");
        cmd.add_option("--set", settings, "scene parameter KEY=VALUE (repeatable)");
        cmd.add_option("--samples", samples, "at most this many intervals between rows")->capture_default_str();
        cmd.add_option("--out", out, "output CSV file")->required();
        cmd.add_flag("--overwrite", overwrite, "replace an --out file that an earlier export wrote");
    }

    ParamOverrides overrides() const { return scene_settings(scene, settings); }
    // The scene, with --t-end and --set applied.
    std::unique_ptr<Scene> make() const {
        ParamOverrides with_t_end = overrides();
        if (!t_end.empty()) with_t_end.push_back({"t_end", {parse_positive(t_end, "--t-end")}});
        return make_scene(scene, with_t_end);
    }

    // Before the work: the file must be new, or one an earlier export wrote and --overwrite.
    void check() const {
        // Bounded like the energy series: 2e9 rows took the machine's 24 GB before being killed.
        if (samples < 1 || samples > max_series_samples)
            throw InputError("--samples must be 1 to " + std::to_string(max_series_samples) + ", not " + std::to_string(samples));
        check_output_file(out, "--out", overwrite, trajectory_header);
    }
    void write(const std::vector<std::vector<double>>& rows, std::ostream& log) const {
        write_output_file(out, table_csv(split_commas(trajectory_header), rows));
        log << "wrote " << out << "\n";
    }
};

class ReferenceVerb final : public Verb {
public:
    void add_options(CLI::App& command) override { o_.add_to(command); }
    int run(const Invocation& how) override {
        const auto scene = o_.make();
        // A granular flow (runs too long to repeat) would be integrated whole to 1e-12, for hours.
        if (scene->scene_traits().times_in_run)
            throw InputError("--scene " + o_.scene + ": a granular scene has no reference trajectory (its schemes are compared with "
                             "each other); rotbench trajectory exports a scheme's");
        o_.check();
        std::vector<std::vector<double>> rows;
        try {
            rows = reference_states(*scene, o_.samples);
        } catch (const InputError&) {
            throw;  // bad input stays exit 2
        } catch (const std::runtime_error& e) {  // Odeint's budget, a non-finite state: the scene's, not rotbench's
            how.err << "rotbench: no reference for " << o_.scene << ": " << e.what() << "; nothing written\n";
            return 1;
        }
        o_.write(rows, how.out);
        return 0;
    }

private:
    ExportOptions o_;
};

class TrajectoryVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        o_.add_to(command);
        command.add_option("--scheme", o_.scheme, "scheme id")->required();
        command.add_option("--dt", o_.dt, "time step in s")->required();
    }
    int run(const Invocation& how) override {
        SchemeRegistry::instance().at(o_.scheme, "scheme");
        const double dt = parse_positive(o_.dt, "--dt");
        const auto scene = o_.make();
        o_.check();
        // A run like any other: a plug-in's in its worker, so that a crash is its failure, not rotbench's.
        Executor executor(how.out, how.err, {.run = {.measure_time = false, .series_samples = o_.samples}, .quiet = true, .verb = "trajectory"});
        RunSpec task{o_.scene, o_.scheme, dt, scene->t_end(), o_.overrides()};
        task.kind = RunKind::states;
        const RunResult r = executor.run(task);
        if (r.interrupted) return executor.interrupted();
        // A blow-up or a throw is the scheme's: its trajectory up to there is written. Running out of
        // memory is rotbench's: nothing is written that could pass for the scheme's.
        if (r.series.empty() || r.failure == out_of_memory_failure) {
            how.err << "rotbench: " << o_.scheme << " " << r.failure << "; nothing written\n";
            return 1;
        }
        o_.write(r.series, how.out);
        if (!r.failure.empty())
            how.err << "rotbench: " << o_.scheme << " " << r.failure << "; " << o_.out << " holds the trajectory up to there\n";
        return 0;
    }

private:
    ExportOptions o_;
};

const RegisterVerb<ReferenceVerb> reference("reference", "export a scene's reference trajectory as CSV");
const RegisterVerb<TrajectoryVerb> trajectory("trajectory", "export one scheme's trajectory on a scene as CSV");

}  // namespace
}  // namespace rotbench
