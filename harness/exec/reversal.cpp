#include "harness/exec/interrupt.hpp"
#include "harness/exec/run_kinds.hpp"
#include "schemes/quaternion.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace rotbench {

RunResult run_reversal(const RunSpec& requested) {
    const auto& entry = SchemeRegistry::instance().at(requested.scheme, "scheme");
    const auto scene = scene_of(requested);
    RunResult result{requested, {}, {}};
    result.spec.t_end = scene->t_end();
    const double dt = requested.dt;
    const std::int64_t steps = step_count(result.spec.t_end, dt);
    const Bodies initial = scene->initial_state();
    Bodies b = initial;
    bool failed = false;
    const auto finite = [&](const Bodies& s) { return std::isfinite(scene->energy(s)); };
    try {
        auto scheme = entry.make();
        std::int64_t evals = 0;
        simulate(*scene, *scheme, b, dt, steps, evals, [&](std::int64_t, double, const Bodies& s) {
            failed = !finite(s);
            return !failed && !interrupt_signal();
        });
        // Back from where the forward steps ended: the forces of the last step are in b, and
        // the scheme keeps its memory, as a reversed integration does.
        for (std::int64_t n = steps - 1; n >= 0 && !failed && !interrupt_signal(); --n) {
            dem_step(*scene, *scheme, b, -dt, static_cast<double>(n) * dt);
            failed = !finite(b);
        }
        if (failed) result.failure = "blew up before returning to t = 0";
    } catch (...) {
        result.failure = caught_failure(requested.scheme);
        failed = true;
    }
    if (interrupt_signal()) {
        result.interrupted = true;
        return result;
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    double angle = failed ? nan : 0.0, omega = failed ? nan : 0.0;
    for (std::size_t i = 0; i < b.size() && !failed; ++i) {
        angle = std::max(angle, rotation_angle_between(b.orientation[i].normalized(), initial.orientation[i].normalized()));
        const double scale = initial.omega[i].norm();
        const double change = (b.omega[i] - initial.omega[i]).norm();
        omega = std::max(omega, scale > 0.0 ? change / scale : change);
    }
    result.metrics = {{metric::reversal_angle, angle},
                      {metric::reversal_omega, omega},
                      {metric::steps, static_cast<double>(steps)},
                      {metric::unstable, failed ? 1.0 : 0.0}};
    return result;
}

}  // namespace rotbench
