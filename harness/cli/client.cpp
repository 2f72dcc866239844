// `rotbench client scene` and `rotbench client check`: the tools of an adapter's author
// (docs/clients.md). `scene` writes the exact scene.json a run would hand the program; `check`
// runs a client file's program once and says what is wrong with its output, or what it measured.
#include "harness/cli/config.hpp"
#include "harness/cli/verb.hpp"
#include "harness/exec/client_run.hpp"
#include "harness/exec/granular_client.hpp"
#include "harness/store/client.hpp"
#include "harness/store/output_dir.hpp"
#include "harness/store/parse.hpp"
#include "schemes/scheme.hpp"

#include <cmath>
#include <fmt/format.h>

namespace rotbench {
namespace {

// The run a client would make: the scene's coarsest default step unless --dt says, the horizon
// run (energy_horizon x the duration) with --horizon.
RunSpec client_task(const std::string& scene_id, const std::string& dt, const std::vector<std::string>& settings, bool horizon) {
    const ParamOverrides params = scene_settings(scene_id, settings);
    const auto scene = make_scene(scene_id, params);
    RunSpec spec{scene_id, "", dt.empty() ? scene->default_dts().front() : parse_positive(dt, "--dt"), scene->t_end(), params};
    spec.kind = horizon ? RunKind::horizon : RunKind::trajectory;
    return spec;
}

class ClientVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.require_subcommand(1);
        CLI::App* scene = command.add_subcommand("scene", "write the scene.json a client's run is handed (stdout, or --out)");
        scene->add_option("scene", scene_, "scene id")->required();
        scene->add_option("--dt", dt_, "time step in s (default: the scene's coarsest)");
        scene->add_option("--set", settings_, "scene parameter KEY=VALUE (repeatable)");
        scene->add_flag("--horizon", horizon_, "the horizon run's: 8 times the duration, as the energy verdicts make it");
        scene->add_option("--out", out_, "write it here (a new file, or one it wrote, with --overwrite)");
        scene->add_flag("--overwrite", overwrite_, "replace an --out file an earlier `client scene` wrote");
        CLI::App* check = command.add_subcommand("check", "run a client file's program once and check its output");
        check->add_option("file", file_, "the client file")->required();
        check->add_option("--scene", scene_, "scene id (default: the first the file lists)");
        check->add_option("--dt", dt_, "time step in s (default: the scene's coarsest)");
        check->add_option("--set", settings_, "scene parameter KEY=VALUE (repeatable)");
        check_ = check;
    }

    int run(const Invocation& how) override { return check_->parsed() ? check(how) : scene(how); }

private:
    int scene(const Invocation& how) const {
        const RunSpec spec = client_task(scene_, dt_, settings_, horizon_);
        const auto made = scene_of(spec);
        const double t_end = horizon_ ? energy_horizon * made->t_end() : made->t_end();
        const std::int64_t steps = step_count(t_end, spec.dt);
        const auto* granular = dynamic_cast<const GranularScene*>(made.get());
        if (granular && horizon_) throw InputError("--horizon: a client runs a granular scene as a trajectory only");
        const std::string json = client_scene_json(*made, spec, t_end, steps);
        if (out_.empty()) {
            how.out << json;
            return 0;
        }
        check_output_file(out_, "--out", overwrite_, "{\n  \"format\": \"rotbench-");
        write_output_file(out_, json);
        how.err << "wrote " << out_ << "\n";
        return 0;
    }

    int check(const Invocation& how) const {
        const std::string id = load_client(file_);
        const LoadedClient& client = *client_of(id);
        const std::string scene_id = scene_.empty() ? client.scenes.front() : scene_;
        if (const std::string why = why_not_taken(id, scene_id); !why.empty()) throw InputError(why);
        RunSpec spec = client_task(scene_id, dt_, settings_, false);
        spec.scheme = id;
        spec.timed = false;
        how.out << fmt::format("client {}: running {} on {} at dt = {:g} ({} steps)\n", id, fmt::join(client.program, " "), scene_id,
                               spec.dt, step_count(scene_of(spec)->t_end(), spec.dt));
        const RunResult r = run_client(spec, {.measure_time = false}, {});
        if (r.interrupted) return 130;
        if (!r.failure.empty()) {
            how.out << "FAIL: " << r.failure << "\n";
            return 1;
        }
        how.out << fmt::format("ok: its output read, {:g} s of wall time ({:g} CPU-s)\n", r.value(metric::client_wall_seconds),
                               r.value(metric::client_cpu_seconds));
        if (r.has(metric::omega_err_max))
            how.out << fmt::format("  relative angular-velocity error {:.3g}, orientation error {:.3g} rad\n",
                                   relative_omega_error(r), r.value(metric::orientation_err_max));
        if (r.has(metric::counterpart_omega_diff_max))
            how.out << fmt::format("  against {}: largest |dw| {:.3g} rad/s, angle {:.3g} rad\n", client.counterpart,
                                   r.value(metric::counterpart_omega_diff_max), r.value(metric::counterpart_angle_diff_max));
        return 0;
    }

    std::string scene_, dt_, out_, file_;
    std::vector<std::string> settings_;
    bool horizon_ = false, overwrite_ = false;
    CLI::App* check_ = nullptr;
};

const RegisterVerb<ClientVerb> client_verb("client", "for adapter authors: write a run's scene.json, or check a client's output");

}  // namespace
}  // namespace rotbench
