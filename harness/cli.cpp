#include "harness/cli.hpp"

#include "harness/config.hpp"
#include "harness/export.hpp"
#include "harness/gate.hpp"
#include "harness/journal.hpp"
#include "harness/parse.hpp"
#include "harness/plugin.hpp"
#include "harness/run_command.hpp"
#include "harness/stability_study.hpp"
#include "harness/sweep.hpp"
#include "reports/gate_report.hpp"
#include "reports/markdown_report.hpp"
#include "reports/output_files.hpp"
#include "reports/results_csv.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <fmt/format.h>

namespace rotbench {
namespace {

// An option given with an empty value ("--scenes ''", often an unset shell variable) is bad
// input, never a silent "the default".
void refuse_empty_values(const CLI::App& app) {
    for (const auto* option : app.get_options())
        for (const auto& value : option->results())
            if (value.empty()) throw InputError(option->get_name() + ": the value is empty; give one or leave the option out");
    for (const auto* sub : app.get_subcommands()) refuse_empty_values(*sub);
}

void list_params(const std::string& scene_id, std::ostream& out) {
    const auto scene = SceneRegistry::instance().at(scene_id, "scene").make();
    out << fmt::format("parameters of {} (--set {}.KEY=VALUE, or [{}] in a config):\n", scene_id, scene_id, scene_id);
    for (const auto& e : scene->params.entries()) {
        std::string value;
        for (double v : e.value) value += fmt::format("{}{}", value.empty() ? "" : ",", v);
        out << fmt::format("  {:<12} {:<24} {:<10} {}\n", e.key, value, e.unit, e.help);
    }
}

void list(std::ostream& out) {
    out << "(rotbench list --params SCENE lists a scene's parameters)\n";
    out << "schemes:\n";
    for (const auto& id : SchemeRegistry::instance().ids()) {
        const auto& e = SchemeRegistry::instance().at(id, "scheme");
        out << fmt::format("  {:<16} {}\n  {:<16} ({})\n", id, e.summary, "", e.source);
    }
    out << "scenes:\n";
    for (const auto& id : SceneRegistry::instance().ids()) {
        const auto& e = SceneRegistry::instance().at(id, "scene");
        const auto scene = make_scene(id);
        std::string dts;
        for (double dt : scene->default_dts()) dts += fmt::format("{}{:g}", dts.empty() ? "" : ",", dt);
        out << fmt::format("  {:<16} {}\n  {:<16} (t_end {:g} s, dt {})\n", id, e.summary, "", scene->t_end(), dts);
    }
}

struct ExportOptionsText {
    std::string scene, scheme, dt, t_end, out;
    std::vector<std::string> settings;
    int samples = 1000;
};

// The scene of an export, with --t-end and --set applied (--set takes KEY=VALUE or SCENE.KEY=VALUE).
std::unique_ptr<Scene> export_scene(const ExportOptionsText& o) {
    SweepSpec spec;
    for (const auto& s : o.settings) add_setting(spec, s.find('.') < s.find('=') ? s : o.scene + "." + s);
    ParamOverrides overrides;
    for (const auto& [scene_id, list] : spec.params) {
        if (scene_id != o.scene) throw InputError("--set names scene '" + scene_id + "', but --scene is '" + o.scene + "'");
        overrides = list;
    }
    if (!o.t_end.empty()) overrides.push_back({"t_end", {parse_positive(o.t_end, "--t-end")}});
    return make_scene(o.scene, overrides);
}

void write_export(const std::string& out, const std::string& csv, std::ostream& log) {
    const std::filesystem::path path(out);
    if (!path.parent_path().empty() && !std::filesystem::is_directory(path.parent_path()))
        throw InputError("--out " + out + ": the directory " + path.parent_path().string() + " does not exist");
    write_file_atomically(path, csv);
    log << "wrote " << out << "\n";
}

int run_cli_arguments(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err,
                      const std::optional<std::filesystem::path>& resuming);

// `run --resume DIR`: the interrupted run's own arguments, run again from the directory it
// was started in (relative paths in them stay right); its journal holds the finished runs.
int resume(const CLI::App& app, const CLI::App& run_cmd, const std::string& dir, std::ostream& out, std::ostream& err) {
    for (const auto* command : {&app, &run_cmd})
        for (const auto* option : command->get_options())
            if (option->count() > 0 && option->get_name() != "--resume")
                throw InputError(option->get_name() + ": --resume DIR takes no other option; the sweep's are read from " +
                                 (std::filesystem::path(dir) / "partial" / "command").string());
    const auto absolute = std::filesystem::absolute(dir);
    const auto arguments = Journal::arguments(absolute);
    const auto here = std::filesystem::current_path();
    std::filesystem::current_path(Journal::working_directory(absolute));
    struct GoBack {
        std::filesystem::path to;
        ~GoBack() {
            std::error_code ec;
            std::filesystem::current_path(to, ec);
        }
    } go_back{here};
    return run_cli_arguments(arguments, out, err, absolute);
}

int run_cli_arguments(const std::vector<std::string>& arguments, std::ostream& out, std::ostream& err,
                      const std::optional<std::filesystem::path>& resuming) {
    std::vector<const char*> argv = {"rotbench"};
    for (const auto& a : arguments) argv.push_back(a.c_str());
    const int argc = static_cast<int>(argv.size());
    CLI::App app{"rotbench: verification and convergence harness for rigid-body rotation schemes"};
    app.require_subcommand(1);
    app.fallthrough();  // --plugin may follow the command
    std::vector<std::string> plugins;
    app.add_option("--plugin", plugins, "load schemes from a plug-in built with rotbench_add_scheme() (repeatable)");
    auto* list_cmd = app.add_subcommand("list", "list the registered schemes and scenes");
    auto* run_cmd = app.add_subcommand("run", "run schemes on scenes and write results.csv and report.md");
    RunOptionsText o;
    add_run_options(*run_cmd, o);
    ExportOptionsText ref_o, traj_o;
    auto* reference_cmd = app.add_subcommand("reference", "export a scene's reference trajectory as CSV");
    auto* trajectory_cmd = app.add_subcommand("trajectory", "export one scheme's trajectory on a scene as CSV");
    for (auto [cmd, o] : {std::pair{reference_cmd, &ref_o}, std::pair{trajectory_cmd, &traj_o}}) {
        cmd->add_option("--scene", o->scene, "scene id")->required();
        cmd->add_option("--t-end", o->t_end, "duration in s (default: the scene's)");
        cmd->add_option("--set", o->settings, "scene parameter KEY=VALUE (repeatable)");
        cmd->add_option("--samples", o->samples, "at most this many intervals between rows")->capture_default_str();
        cmd->add_option("--out", o->out, "output CSV file")->required();
    }
    trajectory_cmd->add_option("--scheme", traj_o.scheme, "scheme id")->required();
    trajectory_cmd->add_option("--dt", traj_o.dt, "time step in s")->required();
    auto* report_cmd = app.add_subcommand("report", "re-render report.md and its plots from the CSVs in DIR");
    std::string report_dir;
    report_cmd->add_option("DIR", report_dir, "a directory written by rotbench run")->required();
    auto* stability_cmd = app.add_subcommand("stability", "stability limits: measured, from eigenvalues, and Peng et al.'s");
    std::string stab_scenes = "sphere_pair,ellipsoid_pair,fast_spin", stab_schemes, stab_zetas = "0,0.1,0.3,0.5",
                stab_omegas = "10,100,1000", stab_out = "rotbench-stability";
    bool stab_overwrite = false;
    int stab_jobs = RunOptionsText::default_jobs();
    stability_cmd->add_option("--scenes", stab_scenes, "contact scenes")->capture_default_str();
    stability_cmd->add_option("--schemes", stab_schemes, "comma list of scheme ids (default: all)");
    stability_cmd->add_option("--zeta", stab_zetas, "damping ratios (contact scenes)")->capture_default_str();
    stability_cmd->add_option("--omega-max", stab_omegas, "spin rates, rad/s (fast_spin)")->capture_default_str();
    stability_cmd->add_option("--out", stab_out, "output directory")->capture_default_str();
    stability_cmd->add_option("--jobs", stab_jobs, "cases in parallel")->check(CLI::Range(1, max_jobs));
    stability_cmd->add_flag("--overwrite", stab_overwrite, "replace results already in --out");
    std::string params_of;
    list_cmd->add_option("--params", params_of, "list the parameters of this scene");
    auto* merge_cmd = app.add_subcommand("merge", "combine the outputs of run --shard K/N into one run's outputs");
    std::vector<std::string> merge_dirs;
    std::string merge_out;
    bool merge_overwrite = false;
    merge_cmd->add_option("DIRS", merge_dirs, "the shard directories, one per K")->required();
    merge_cmd->add_option("--out", merge_out, "output directory")->required();
    merge_cmd->add_flag("--overwrite", merge_overwrite, "replace results already in --out");
    auto* gate_cmd = app.add_subcommand("gate", "run the checks of a gate file; exit 1 if any fails");
    std::string gate_file, gate_junit_file, gate_out;
    int gate_jobs = o.jobs;
    bool gate_overwrite = false;
    gate_cmd->add_option("FILE", gate_file, "gate file (TOML, [[check]] tables)")->required();
    gate_cmd->add_option("--junit", gate_junit_file, "write JUnit XML here (one test case per check and scheme)");
    gate_cmd->add_option("--out", gate_out, "also write gate.csv and results.csv of the runs here");
    gate_cmd->add_option("--jobs", gate_jobs, "runs in parallel (results do not depend on it)")->check(CLI::Range(1, max_jobs));
    gate_cmd->add_flag("--overwrite", gate_overwrite, "replace a gate.csv already in --out");

    std::string command_line = "rotbench";
    for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
    try {
        const std::vector<std::string> commands = {list_cmd->get_name(), run_cmd->get_name(), reference_cmd->get_name(),
                                                   trajectory_cmd->get_name(), report_cmd->get_name(),
                                                   stability_cmd->get_name(), gate_cmd->get_name(),
                                                   merge_cmd->get_name()};
        if (argc > 1 && argv[1][0] != '-' && std::find(commands.begin(), commands.end(), argv[1]) == commands.end())
            throw InputError(std::string("unknown command '") + argv[1] + "'; valid commands: " + join(commands, ", "));
        app.parse(argc, argv.data());
        refuse_empty_values(app);
        if (*run_cmd && !o.resume.empty()) {
            if (resuming) throw InputError("--resume: " + (*resuming / "partial" / "command").string() + " holds --resume itself");
            return resume(app, *run_cmd, o.resume, out, err);
        }
        for (const auto& plugin : plugins) {
            const auto ids = load_plugin(plugin);
            err << "rotbench: loaded " << join(ids, ", ") << " from " << plugin << "\n";
        }
        if (*merge_cmd) {
            std::vector<std::filesystem::path> dirs(merge_dirs.begin(), merge_dirs.end());
            const auto results = merge_shards(dirs);
            write_outputs(prepare_output(merge_out, "results.csv", merge_overwrite), results, command_line, out);
            return 0;
        }
        if (*gate_cmd) {
            const auto checks = load_gate(gate_file);
            std::filesystem::path dir;
            if (!gate_out.empty()) dir = prepare_output(gate_out, "gate.csv", gate_overwrite);
            if (!gate_junit_file.empty()) {
                const std::filesystem::path parent = std::filesystem::path(gate_junit_file).parent_path();
                if (!parent.empty() && !std::filesystem::is_directory(parent))
                    throw InputError("--junit " + gate_junit_file + ": the directory " + parent.string() + " does not exist");
            }
            const GateResult result = run_gate(checks, gate_jobs);
            out << gate_summary(checks, result);
            if (!gate_junit_file.empty()) write_file_atomically(gate_junit_file, gate_junit(checks, result));
            if (!dir.empty()) {
                write_file_atomically(dir / "gate.csv", gate_csv(checks, result));
                write_file_atomically(dir / "results.csv", results_csv(result.runs));
            }
            const bool passed = std::all_of(result.outcomes.begin(), result.outcomes.end(), [](const GateOutcome& g) { return g.passed; });
            return passed ? 0 : 1;
        }
        if (*list_cmd) {
            if (params_of.empty()) list(out);
            else list_params(params_of, out);
            return 0;
        }
        if (*stability_cmd) {
            const auto scenes = parse_id_list(stab_scenes, SceneRegistry::instance(), "scene");
            const auto schemes = stab_schemes.empty() ? SchemeRegistry::instance().ids()
                                                      : parse_id_list(stab_schemes, SchemeRegistry::instance(), "scheme");
            const auto zetas = parse_nonnegative_list(stab_zetas, "--zeta");
            const auto omegas = parse_positive_list(stab_omegas, "--omega-max");
            check_stability_scenes(scenes);
            const auto dir = prepare_output(stab_out, "stability.csv", stab_overwrite);
            const auto rows = stability_study(scenes, schemes, zetas, omegas, stab_jobs);
            write_file_atomically(dir / "stability.csv", stability_csv(rows));
            write_file_atomically(dir / "stability_spin.csv", stability_spin_csv(rows));
            write_file_atomically(dir / "stability.md", "# rotbench stability\n\nCommand: `" + command_line + "`\n\n" +
                                                            stability_section(rows, dir) +
                                                            spectral_radius_plots(scenes, schemes, dir));
            out << "wrote " << (dir / "stability.csv").string() << " and " << (dir / "stability.md").string() << "\n";
            return 0;
        }
        if (*report_cmd) {
            const auto results = read_results(report_dir);
            write_file_atomically(std::filesystem::path(report_dir) / "report.md", markdown_report(results, command_line, report_dir));
            out << "wrote " << (std::filesystem::path(report_dir) / "report.md").string() << "\n";
            return 0;
        }
        if (*reference_cmd) {
            write_export(ref_o.out, reference_csv(*export_scene(ref_o), ref_o.samples), out);
            return 0;
        }
        if (*trajectory_cmd) {
            SchemeRegistry::instance().at(traj_o.scheme, "scheme");
            const double dt = parse_positive(traj_o.dt, "--dt");
            write_export(traj_o.out, scheme_trajectory_csv(*export_scene(traj_o), traj_o.scheme, dt, traj_o.samples), out);
            return 0;
        }
        return run_command(o, arguments, command_line, out, err, resuming);
    } catch (const CLI::CallForHelp&) {
        out << app.help();
        return 0;
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) {
            out << app.help();
            return 0;
        }
        err << "rotbench: " << e.what() << " (see rotbench --help)\n";
        return 2;
    } catch (const InputError& e) {
        err << "rotbench: " << e.what() << "\n";
        return 2;
    } catch (const std::filesystem::filesystem_error& e) {  // an output path that is not a writable directory
        err << "rotbench: " << e.what() << "\n";
        return 2;
    }
}

}  // namespace

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    return run_cli_arguments(std::vector<std::string>(argv + 1, argv + argc), out, err, std::nullopt);
}

}  // namespace rotbench
