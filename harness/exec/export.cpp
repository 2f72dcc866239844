#include "harness/exec/export.hpp"

#include "harness/exec/interrupt.hpp"
#include "harness/exec/run_kinds.hpp"
#include "harness/store/parse.hpp"
#include "references/odeint_reference.hpp"
#include "schemes/quaternion.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {

std::vector<double> state_row(const Scene& scene, double t, const Bodies& b) {
    const Quat q = b.orientation[0];
    const Vec3 w = b.omega[0], wb = to_body(q, w), x = b.position[0], v = b.velocity[0];
    return {t,      q.w(),  q.x(), q.y(), q.z(), w.x(), w.y(), w.z(), wb.x(),
            wb.y(), wb.z(), x.x(), x.y(), x.z(), v.x(), v.y(), v.z(), scene.energy(b)};
}

std::vector<std::vector<double>> reference_states(const Scene& scene, int samples) {
    if (samples < 1) throw InputError("--samples must be at least 1");
    const std::vector<double> times = equally_spaced_times(scene.t_end(), samples);
    std::vector<std::vector<double>> rows;
    Bodies b = scene.initial_state();
    const Vec3 x0 = b.position[0], v0 = b.velocity[0];
    if (scene.reference_kind() == Scene::ReferenceKind::closed_form) {
        for (double t : times) {
            const ReferenceState s = scene.exact(0, t);
            b.orientation.set(0, s.q);
            b.omega.set(0, s.omega);
            b.position.set(0, x0 + v0 * t);
            rows.push_back(state_row(scene, t, b));
        }
        return rows;
    }
    const Trajectory trajectory =
        integrate_scene(scene, times, OdeMethod::fehlberg78, reference_tolerance, [] { return !interrupt_signal(); });
    for (std::size_t k = 0; k < times.size(); ++k) {
        const ReferenceState s = trajectory.state(k, 0);
        b.orientation.set(0, s.q);
        b.omega.set(0, s.omega);
        b.position.set(0, trajectory.position(k, 0));
        b.velocity.set(0, trajectory.velocity(k, 0));
        rows.push_back(state_row(scene, times[k], b));
    }
    return rows;
}

RunResult run_states(const RunSpec& requested, const RunOptions& options) {
    const int samples = options.series_samples;
    if (samples < 1) throw InputError("--samples must be at least 1");
    const auto& entry = SchemeRegistry::instance().at(requested.scheme, "scheme");
    const auto scene = scene_of(requested);
    RunResult result{requested, {}, {}};
    result.spec.t_end = scene->t_end();
    result.series_columns = split_commas(trajectory_header);
    const double dt = requested.dt;
    const std::int64_t steps = step_count(result.spec.t_end, dt);
    const std::int64_t stride = std::max<std::int64_t>(1, (steps + samples - 1) / samples);
    Bodies b = scene->initial_state();
    result.series.push_back(state_row(*scene, 0.0, b));
    std::int64_t evals = 0, last = 0;
    try {
        auto scheme = entry.make();
        simulate(*scene, *scheme, b, dt, steps, evals, [&](std::int64_t n, double t, const Bodies& state) {
            const Quat q = state.orientation[0];
            if (!q.coeffs().allFinite() || !state.omega[0].allFinite() || !std::isfinite(scene->energy(state))) {
                result.failure = fmt::format("blew up at step {} (t = {:g} s)", n, t);
                return false;
            }
            last = n;
            if (n % stride == 0 || n == steps) result.series.push_back(state_row(*scene, t, state));
            return !interrupt_signal();
        });
    } catch (...) {
        result.failure = fmt::format("{} (after step {})", caught_failure(requested.scheme), last);
    }
    if (interrupt_signal()) result = {result.spec, {}, {}, true};
    return result;
}

}  // namespace rotbench
