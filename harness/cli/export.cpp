// `rotbench reference` and `rotbench trajectory`: a scene's reference trajectory, or one
// scheme's run on it, as CSV (harness/engine/export.hpp gives the columns).
#include "harness/cli/verb.hpp"
#include "harness/engine/export.hpp"
#include "harness/engine/sweep.hpp"
#include "harness/io/config.hpp"
#include "harness/io/output_files.hpp"
#include "harness/io/parse.hpp"
#include "schemes/scheme.hpp"

#include <filesystem>

namespace rotbench {
namespace {

struct ExportOptions {
    std::string scene, scheme, dt, t_end, out;
    std::vector<std::string> settings;
    int samples = 1000;

    void add_to(CLI::App& cmd) {
        cmd.add_option("--scene", scene, "scene id")->required();
        cmd.add_option("--t-end", t_end, "duration in s (default: the scene's)");
        cmd.add_option("--set", settings, "scene parameter KEY=VALUE (repeatable)");
        cmd.add_option("--samples", samples, "at most this many intervals between rows")->capture_default_str();
        cmd.add_option("--out", out, "output CSV file")->required();
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

    void write(const std::string& csv, std::ostream& log) const {
        const std::filesystem::path path(out);
        if (!path.parent_path().empty() && !std::filesystem::is_directory(path.parent_path()))
            throw InputError("--out " + out + ": the directory " + path.parent_path().string() + " does not exist");
        write_file_atomically(path, csv);
        log << "wrote " << out << "\n";
    }
};

class ReferenceVerb final : public Verb {
public:
    void add_options(CLI::App& command) override { o_.add_to(command); }
    int run(const Invocation& how) override {
        o_.write(reference_csv(*o_.make(), o_.samples), how.out);
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
        o_.write(scheme_trajectory_csv(*o_.make(), o_.scheme, dt, o_.samples), how.out);
        return 0;
    }

private:
    ExportOptions o_;
};

const RegisterVerb<ReferenceVerb> reference("reference", "export a scene's reference trajectory as CSV");
const RegisterVerb<TrajectoryVerb> trajectory("trajectory", "export one scheme's trajectory on a scene as CSV");

}  // namespace
}  // namespace rotbench
