#include "harness/exec/client_run.hpp"

#include "harness/exec/contact_client.hpp"
#include "harness/exec/granular_client.hpp"
#include "harness/exec/json_vec.hpp"
#include "harness/exec/run_kinds.hpp"
#include "harness/store/client.hpp"
#include "harness/store/parse.hpp"
#include "harness/store/output_files.hpp"
#include "schemes/quaternion.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace rotbench {
namespace {

namespace fs = std::filesystem;
using Row = TrajectoryRow;

// The program's trajectory, stepped through as if a scheme made it: each step takes the next row.
class Replay final : public RotationScheme {
public:
    explicit Replay(const std::vector<Row>& rows) : rows_(rows) {}
    void start(const Bodies&) override { next_ = 1; }
    void predict(Bodies& b, double) override {
        const Row& r = rows_.at(next_++);
        b.orientation.set(0, Quat(r[1], r[2], r[3], r[4]));
        b.omega.set(0, Vec3(r[5], r[6], r[7]));
    }
    void correct(Bodies&, double) override {}

private:
    const std::vector<Row>& rows_;
    std::size_t next_ = 1;
};

// A directory of rotbench's own for one run of the program; removed, with all it holds, when it goes.
struct Scratch {
    fs::path path;
    Scratch() {
        const fs::path base = std::getenv("TMPDIR") && *std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp";
        std::string pattern = (base / "rotbench-client-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw OutputError("cannot make a scratch directory in " + base.string());
        path = pattern;
    }
    ~Scratch() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

// The states a built-in scheme makes on the scene at the same step, as the rows a program writes.
std::vector<Row> builtin_rows(const Scene& scene, const std::string& scheme_id, double dt, std::int64_t steps) {
    Bodies b = scene.initial_state();
    auto scheme = registered_scheme(scheme_id)();
    const auto row = [dt](std::int64_t n, const Bodies& state) {
        const Quat& q = state.orientation[0];
        const Vec3& w = state.omega[0];
        return Row{static_cast<double>(n) * dt, q.w(), q.x(), q.y(), q.z(), w.x(), w.y(), w.z()};
    };
    std::vector<Row> rows = {row(0, b)};
    std::int64_t evals = 0;
    simulate(scene, *scheme, b, dt, steps, evals, [&](std::int64_t n, double, const Bodies& state) {
        rows.push_back(row(n, state));
        return std::isfinite(state.omega[0].norm());
    });
    return rows;
}

// The largest differences between two trajectories of the same scene and step after t = 0 (the
// given state): the angular velocity's and the orientation's angle; NaN when the other has no
// trajectory (its program failed), inf when it stopped short (blew up).
void add_counterpart_difference(RunResult& result, const std::vector<Row>& rows, const std::vector<Row>& other) {
    double omega_diff = other.empty() ? NAN : 0.0, angle_diff = omega_diff;
    for (std::size_t n = 1; n < rows.size() && n < other.size(); ++n) {
        const Row &a = rows[n], &b = other[n];
        omega_diff = std::max(omega_diff, (Vec3(a[5], a[6], a[7]) - Vec3(b[5], b[6], b[7])).norm());
        angle_diff = std::max(angle_diff, rotation_angle_between(Quat(a[1], a[2], a[3], a[4]).normalized(), Quat(b[1], b[2], b[3], b[4]).normalized()));
    }
    if (!other.empty() && other.size() < rows.size()) omega_diff = angle_diff = INFINITY;
    result.metrics.emplace_back(metric::counterpart_omega_diff_max, omega_diff);
    result.metrics.emplace_back(metric::counterpart_angle_diff_max, angle_diff);
}

// The client's program on one scene.json, in a scratch directory of its own that goes with all
// the program left in it: its output, and what `read` (called only when it exited 0) made of the
// file it wrote, named `output`.
WorkerOutput run_in_scratch(const LoadedClient& client, const std::string& scene_json, const std::string& output, double seconds,
                            std::size_t megabytes, const std::function<void(const fs::path&)>& read) {
    const Scratch scratch;
    write_file_atomically(scratch.path / "scene.json", scene_json);
    std::vector<std::string> args = client.program;
    args.insert(args.end(), {"scene.json", output});
    WorkerOutput out = run_program(args, scratch.path.string(), seconds, megabytes, "program");
    if (!out.interrupted && out.failure.empty() && out.exit_status == 0) read(scratch.path / output);
    return out;
}

// The program's own cost, whatever became of its output: a slow rung is found by it.
RunResult timed(RunResult r, double cpu_seconds, double wall_seconds) {
    r.metrics.emplace_back(metric::client_cpu_seconds, cpu_seconds);
    r.metrics.emplace_back(metric::client_wall_seconds, wall_seconds);
    return r;
}

RunResult declined_run(const RunSpec& spec, const std::string& last_error_line) {
    return RunResult{spec, {{metric::declined, 1.0}}, "declined" + last_error_line};
}

// A built-in's stability search (harness/exec/stability.hpp: the same criterion, horizon and
// bisection) with each trial one run of the program over the horizon, judged on its states.
// A trial that fails or is declined ends the search with no limit: a failed program is not
// evidence of a blow-up; states that are not finite are.
RunResult contact_stability_search(const LoadedClient& client, const RunSpec& requested, const ContactPairScene& scene, double seconds,
                                   std::size_t megabytes, RunResult result) {
    const StabilityCriterion criterion = stability_criterion(scene);
    double cpu = 0, wall = 0;
    std::string stop;  // why the search has no limit
    bool declined = false, interrupted = false;
    const auto unstable = [&](double dt) {
        if (!stop.empty() || interrupted) return true;  // the search runs out with no more trials
        RunSpec trial = requested;
        trial.dt = dt;
        const auto steps = static_cast<std::int64_t>(std::ceil(criterion.horizon / dt));
        std::vector<Row> rows;
        std::string why;
        const WorkerOutput out = run_in_scratch(
            client, contact_scene_json(scene, trial, static_cast<double>(steps) * dt, steps), "trajectory.csv",
            seconds > 0 ? seconds : steps_timeout(2.0 * static_cast<double>(steps)), megabytes,
            [&](const fs::path& file) { why = read_trajectory(file, contact_trajectory, steps, dt, rows); });
        cpu += out.cpu_seconds, wall += out.wall_seconds;
        interrupted = out.interrupted;
        if (out.exit_status == client_declines) declined = true, stop = out.last_error_line;
        else if (!out.failure.empty() || !why.empty())
            stop = fmt::format("at dt = {}: {}{}", format_number(dt), out.failure.empty() ? why : out.failure, out.last_error_line);
        return interrupted || !stop.empty() || contact_blew_up(scene, rows, criterion);
    };
    const double peng = scene.predicted_limit();
    // Down to Peng's step / 64 at most: a program writes every step of a trial (a built-in stops
    // at the blow-up), 64 000 periods' worth there. 0 below that, as for a built-in below 2^-30.
    const double limit = stability_boundary(unstable, peng, stability_tolerance, 6);
    if (interrupted) return RunResult{result.spec, {}, {}, true};
    if (declined) return timed(declined_run(result.spec, stop), cpu, wall);
    if (!stop.empty()) {
        result.failure = stop;
        return timed(std::move(result), cpu, wall);
    }
    result.metrics = {{metric::dt_empirical, limit}, {metric::dt_peng, peng}, {metric::stability_ratio, limit / peng}};
    return timed(std::move(result), cpu, wall);
}

std::string one_body_scene_json(const Scene& scene, const RunSpec& spec, double t_end, std::int64_t steps) {
    const auto law = scene.torque_law();
    const Bodies b = scene.initial_state();
    if (!law || b.size() != 1) throw InputError("scene '" + spec.scene + "' is not one body under a torque law a client can take");
    const Quat q0 = b.orientation[0];
    const Vec3 inertia = b.inertia[0], w_world = b.omega[0], w_body = to_body(q0, w_world);
    const Vec3 l_body = inertia.cwiseProduct(w_body);
    nlohmann::ordered_json torque = {{"law", law->law}};
    for (const auto& [name, value] : law->parameters) torque[name] = json_vec(value);
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (const auto& [key, values] : spec.params) params[key] = values;
    const nlohmann::ordered_json j = {{"format", "rotbench-client-scene 1"},
                              {"scene", spec.scene},
                              {"mass", b.mass[0]},
                              {"inertia_body", json_vec(inertia)},
                              {"q0", {q0.w(), q0.x(), q0.y(), q0.z()}},
                              {"omega0_world", json_vec(w_world)},
                              {"omega0_body", json_vec(w_body)},
                              {"L0_world", json_vec(to_world(q0, l_body))},
                              {"L0_body", json_vec(l_body)},
                              {"torque", torque},
                              {"dt", spec.dt},
                              {"t_end", t_end},
                              {"steps", steps},
                              {"columns", client_trajectory_header},
                              {"params", params}};  // last: the user's keys (q0 as typed) after the scene's own
    return j.dump(2) + "\n";
}

}  // namespace

std::string client_scene_json(const Scene& scene, const RunSpec& spec, double t_end, std::int64_t steps) {
    if (const auto* granular = dynamic_cast<const GranularScene*>(&scene)) return granular_scene_json(*granular, spec, t_end, steps);
    if (const auto* contact = dynamic_cast<const ContactPairScene*>(&scene)) return contact_scene_json(*contact, spec, t_end, steps);
    return one_body_scene_json(scene, spec, t_end, steps);
}

RunResult run_client(const RunSpec& requested, const RunOptions& options, const IsolationLimits& limits) {
    const LoadedClient& client = *client_of(requested.scheme);
    const auto scene = scene_of(requested);
    RunResult failed{requested, {}, {}};
    failed.spec.t_end = scene->t_end();
    const auto fail = [&](const std::string& why) {
        failed.failure = why;
        failed.metrics = {{metric::unstable, 1.0}};
        return failed;
    };
    auto* granular = dynamic_cast<GranularScene*>(scene.get());
    const auto* contact = dynamic_cast<const ContactPairScene*>(scene.get());
    const bool stability = requested.kind == RunKind::stability && contact;
    if (requested.kind != RunKind::trajectory && requested.kind != RunKind::horizon && !stability)
        return fail(fmt::format("a client makes runs of kind trajectory and horizon{}, not {}", contact ? " (stability on a contact scene)" : "",
                                kind_name(requested.kind)));
    if (const std::string why = why_not_taken(requested.scheme, requested.scene); !why.empty()) return fail(why);
    if (granular && requested.kind != RunKind::trajectory) return fail("a client runs a granular scene as a trajectory only");
    const std::size_t megabytes = limits.megabytes ? limits.megabytes : isolation_memory(1);
    if (stability) return contact_stability_search(client, requested, *contact, limits.seconds, megabytes, failed);
    const double t_end = requested.kind == RunKind::horizon ? energy_horizon * scene->t_end() : scene->t_end();
    const std::int64_t steps = step_count(t_end, requested.dt);
    std::string scene_json;
    try {
        scene_json = client_scene_json(*scene, requested, t_end, steps);
    } catch (const InputError& e) {  // a scene its client file lists but no spec can describe
        return fail(e.what());
    }
    const TrajectoryLayout& layout = contact ? contact_trajectory : one_body_trajectory;
    const double body_steps = static_cast<double>(steps) * static_cast<double>(scene->initial_state().size());
    const double seconds = limits.seconds > 0 ? limits.seconds : steps_timeout(body_steps);
    const std::string output = granular ? "samples.csv" : "trajectory.csv";
    RunResult replayed;
    std::vector<Row> rows;
    std::string why;
    const WorkerOutput out = run_in_scratch(client, scene_json, output, seconds, megabytes, [&](const fs::path& file) {
        if (granular) replayed = replay_granular_samples(requested, *granular, file, steps);
        else why = read_trajectory(file, layout, steps, requested.dt, rows);
    });
    if (out.interrupted) return RunResult{failed.spec, {}, {}, true};
    if (out.exit_status == client_declines) return timed(declined_run(failed.spec, out.last_error_line), out.cpu_seconds, out.wall_seconds);
    if (!out.failure.empty()) return timed(fail(out.failure), out.cpu_seconds, out.wall_seconds);
    if (granular) {
        if (!replayed.failure.empty()) replayed.failure += out.last_error_line;
        replayed.spec.t_end = t_end;
        replayed.metrics.emplace_back(metric::client_cpu_seconds_per_simulated_second, out.cpu_seconds / t_end);
        return timed(std::move(replayed), out.cpu_seconds, out.wall_seconds);
    }
    if (!why.empty()) return timed(fail(why + out.last_error_line), out.cpu_seconds, out.wall_seconds);
    const SchemeFactory replay = [&rows, contact]() -> std::unique_ptr<RotationScheme> {
        if (contact) return contact_replay(rows);
        return std::make_unique<Replay>(rows);
    };
    if (requested.kind == RunKind::horizon) return timed(run_horizon(requested, replay), out.cpu_seconds, out.wall_seconds);
    RunResult result = run_trajectory(requested, {.measure_time = false, .series_samples = options.series_samples}, replay);
    // On a contact scene the counterpart's comparison is not made (it compares one body's rotation).
    if (!client.counterpart.empty() && result.failure.empty() && !contact) {
        // Another client (another version of the same code): its program on the same scene.json, on
        // a scene its file takes; elsewhere nothing to compare with.
        std::vector<Row> other;
        if (const LoadedClient* counterpart = client_of(client.counterpart)) {
            if (why_not_taken(counterpart->id, requested.scene).empty()) {
                const WorkerOutput their = run_in_scratch(*counterpart, scene_json, output, seconds, megabytes, [&](const fs::path& file) {
                    if (!read_trajectory(file, one_body_trajectory, steps, requested.dt, other).empty()) other.clear();
                });
                if (their.interrupted) return RunResult{failed.spec, {}, {}, true};
            }
        } else {
            other = builtin_rows(*scene, client.counterpart, requested.dt, steps);
        }
        add_counterpart_difference(result, rows, other);
    }
    return timed(std::move(result), out.cpu_seconds, out.wall_seconds);
}

}  // namespace rotbench
