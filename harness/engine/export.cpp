#include "harness/engine/export.hpp"

#include "harness/engine/interrupt.hpp"
#include "harness/engine/run.hpp"
#include "references/odeint_reference.hpp"
#include "harness/io/output_files.hpp"
#include "schemes/quaternion.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace rotbench {
namespace {

// One row from the state of body 0 in `b` (its energy: the scene's total).
std::string row(const Scene& scene, double t, const Bodies& b) {
    const Quat q = b.orientation[0];
    const Vec3 w = b.omega[0], wb = to_body(q, w), x = b.position[0], v = b.velocity[0];
    const double values[] = {t,     q.w(),  q.x(),  q.y(),  q.z(), w.x(), w.y(), w.z(), wb.x(),
                             wb.y(), wb.z(), x.x(), x.y(), x.z(), v.x(), v.y(), v.z(), scene.energy(b)};
    std::string line;
    for (double value : values) line += (line.empty() ? "" : ",") + format_number(value);
    return line + "\n";
}

}  // namespace

std::string reference_csv(const Scene& scene, int samples) {
    if (samples < 1) throw InputError("--samples must be at least 1");
    const double t_end = scene.t_end();
    const std::vector<double> times = equally_spaced_times(t_end, samples);
    std::string csv = std::string(trajectory_header) + "\n";
    Bodies b = scene.initial_state();
    const Vec3 x0 = b.position[0], v0 = b.velocity[0];
    if (scene.reference_kind() == Scene::ReferenceKind::closed_form) {
        for (double t : times) {
            const ReferenceState s = scene.exact(0, t);
            b.orientation.set(0, s.q);
            b.omega.set(0, s.omega);
            b.position.set(0, x0 + v0 * t);
            csv += row(scene, t, b);
        }
        return csv;
    }
    const Trajectory trajectory =
        integrate_scene(scene, times, OdeMethod::fehlberg78, reference_tolerance, [] { return !interrupt_signal(); });
    for (std::size_t k = 0; k < times.size(); ++k) {
        const ReferenceState s = trajectory.state(k, 0);
        b.orientation.set(0, s.q);
        b.omega.set(0, s.omega);
        b.position.set(0, trajectory.position(k, 0));
        b.velocity.set(0, trajectory.velocity(k, 0));
        csv += row(scene, times[k], b);
    }
    return csv;
}

std::string scheme_trajectory_csv(const Scene& scene, const std::string& scheme_id, double dt, int samples, std::string* stopped) {
    if (samples < 1) throw InputError("--samples must be at least 1");
    const std::int64_t steps = step_count(scene.t_end(), dt);
    const std::int64_t stride = std::max<std::int64_t>(1, (steps + samples - 1) / samples);
    auto scheme = SchemeRegistry::instance().at(scheme_id, "scheme").make();
    Bodies b = scene.initial_state();
    std::string csv = std::string(trajectory_header) + "\n" + row(scene, 0.0, b);
    std::int64_t evals = 0, last = 0;
    std::string why;
    try {
        simulate(scene, *scheme, b, dt, steps, evals, [&](std::int64_t n, double t, const Bodies& state) {
            const Quat q = state.orientation[0];
            if (!q.coeffs().allFinite() || !state.omega[0].allFinite() || !std::isfinite(scene.energy(state))) {
                why = fmt::format("blew up at step {} (t = {:g} s)", n, t);
                return false;
            }
            last = n;
            if (n % stride == 0 || n == steps) csv += row(scene, t, state);
            return true;
        });
    } catch (const std::exception& e) {
        why = fmt::format("threw after step {}: {}", last, e.what());
    } catch (...) {
        why = fmt::format("threw after step {}", last);
    }
    if (stopped) *stopped = why;
    return csv;
}

}  // namespace rotbench
