// `rotbench reference` and `rotbench trajectory`: a scene's reference trajectory, or one
// scheme's run on it, as CSV (harness/engine/export.hpp gives the columns).
#include "harness/cli/verb.hpp"
#include "harness/engine/export.hpp"
#include "harness/engine/sweep.hpp"
#include "harness/io/config.hpp"
#include "harness/io/output_dir.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/parse.hpp"
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

    // The scene, with --t-end and --set applied (--set takes KEY=VALUE or SCENE.KEY=VALUE).
    std::unique_ptr<Scene> make() const {
        SweepSpec spec;
        for (const auto& s : settings) add_setting(spec, s.find('.') < s.find('=') ? s : scene + "." + s);
        ParamOverrides overrides;
        for (const auto& [scene_id, list] : spec.params) {
            if (scene_id != scene) throw InputError("--set names scene '" + scene_id + "', but --scene is '" + scene + "'");
            overrides = list;
        }
        if (!t_end.empty()) overrides.push_back({"t_end", {parse_positive(t_end, "--t-end")}});
        return make_scene(scene, overrides);
    }

    // Before the work: the file must be new, or one an earlier export wrote and --overwrite.
    void check() const {
        if (samples < 1) throw InputError("--samples must be at least 1");
        check_output_file(out, "--out", overwrite, trajectory_header);
    }
    void write(const std::string& csv, std::ostream& log) const {
        write_file_atomically(out, csv);
        log << "wrote " << out << "\n";
    }
};

class ReferenceVerb final : public Verb {
public:
    void add_options(CLI::App& command) override { o_.add_to(command); }
    int run(const Invocation& how) override {
        const auto scene = o_.make();
        o_.check();
        o_.write(reference_csv(*scene, o_.samples), how.out);
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
        std::string stopped;
        o_.write(scheme_trajectory_csv(*scene, o_.scheme, dt, o_.samples, &stopped), how.out);
        if (!stopped.empty())
            how.err << "rotbench: " << o_.scheme << " " << stopped << "; " << o_.out << " holds the trajectory up to there\n";
        return 0;
    }

private:
    ExportOptions o_;
};

const RegisterVerb<ReferenceVerb> reference("reference", "export a scene's reference trajectory as CSV");
const RegisterVerb<TrajectoryVerb> trajectory("trajectory", "export one scheme's trajectory on a scene as CSV");

}  // namespace
}  // namespace rotbench
