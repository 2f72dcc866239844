#include "harness/exec/run.hpp"

#include "harness/exec/interrupt.hpp"
#include "harness/exec/timed_scheme.hpp"
#include "harness/exec/timing.hpp"
#include "harness/exec/reference.hpp"
#include "harness/exec/run_kinds.hpp"
#include "harness/store/plugin.hpp"
#include "schemes/quaternion.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fmt/format.h>
#include <limits>

namespace rotbench {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Every scene's energy includes the rotational kinetic energy, into which every angular
// velocity and orientation enters: a NaN or Inf in any of them makes the energy NaN or Inf
// (tests/test_scenes.cpp checks this for every scene). So beside the energy, only the
// positions and velocities need a test of their own (a scene without translation leaves
// them out of its energy). x * 0 is 0 for a finite x and NaN otherwise: one test per body
// instead of one per component.
bool finite_translation(const Bodies& b) {
    for (std::size_t i = 0; i < b.size(); ++i)
        if ((0.0 * b.position[i]).sum() + (0.0 * b.velocity[i]).sum() != 0.0) return false;
    return true;
}

// Accumulates the per-step errors and drifts of one run. Samples are the states after
// each full step, t = dt, 2 dt, ..., N dt (the initial state is exact by construction).
//
// It runs at every step of every run, a good share of a cheap step (docs/performance.md). So
// it keeps, per step, only the maxima of the raw quantities (|E - E0|, |q|^2, |L - L0|^2, |w - w_ref|^2)
// and scales them, or takes their square roots, once at the end. Correctly rounded division
// and sqrt are monotone, so the maximum of the scaled values is the scaled maximum, bit for
// bit.
class MetricsObserver {
public:
    MetricsObserver(const Scene& scene, const Reference* reference, const Bodies& initial, std::int64_t series_stride)
        : scene_(scene),
          reference_(reference),
          series_stride_(series_stride),
          conserves_energy_(scene.conserves_energy()),
          gains_energy_(scene.gains_energy()),
          energy0_(scene.energy(initial)),
          energy_scale_(std::max(std::abs(energy0_), kinetic_energy(initial))),
          runaway_limit_(blowup_energy_factor * energy_scale_),
          tracks_energy_drift_(energy0_ != 0.0 && conserves_energy_),
          momentum0_(total_angular_momentum(initial)),
          tracks_momentum_drift_(scene.conserves_angular_momentum() && momentum0_.norm() > 0.0),
          probe_(scene.make_probe()) {
        if (series_stride_ > 0) {
            series_columns_ = {"t", "energy_error"};
            for (const auto& part : scene_.energy_parts(initial)) series_columns_.push_back(part.first);
            record(0.0, initial);
        }
    }

    bool operator()(std::int64_t n, double t, const Bodies& b) {
        if (interrupt_signal()) return false;
        const double energy = finite_translation(b) ? scene_.energy(b) : nan;
        const double change = energy - energy0_;
        const bool runaway = conserves_energy_ ? std::abs(change) > runaway_limit_ : !gains_energy_ && change > runaway_limit_;
        if (!std::isfinite(energy) || runaway) {
            fail_step_ = n;
            fail_time_ = t;
            return false;
        }
        if (tracks_energy_drift_) {
            if (std::abs(change) > energy_change_max_) {  // the drift only changes with the maximum
                energy_change_max_ = std::abs(change);
                energy_drift_ = energy_change_max_ / std::abs(energy0_);
            }
            envelope_fit_.add(t, energy_drift_);
        }
        if (series_stride_ > 0 && --until_record_ == 0) {
            record(t, b);
            until_record_ = series_stride_;
        }
        if (tracks_momentum_drift_)
            momentum_change_sq_max_ = std::max(momentum_change_sq_max_, (total_angular_momentum(b) - momentum0_).squaredNorm());
        for (std::size_t i = 0; i < b.size(); ++i) {
            const double norm_sq = b.orientation[i].squaredNorm();
            quat_norm_sq_max_ = std::max(quat_norm_sq_max_, norm_sq);
            quat_norm_sq_min_ = std::min(quat_norm_sq_min_, norm_sq);
        }
        if (reference_) compare_with_reference(n, t, b);
        if (probe_) probe_->observe(t, b);
        return true;
    }

    bool unstable() const { return fail_step_ != 0; }

    void write(RunResult& r) const {
        auto add = [&](std::string_view name, double v) { r.metrics.emplace_back(name, unstable() ? nan : v); };
        if (reference_) {
            const Vec3 rms = (squared_error_sum_ / static_cast<double>(std::max<std::int64_t>(samples_, 1))).cwiseSqrt();
            add(metric::omega_rms_x, rms.x());
            add(metric::omega_rms_y, rms.y());
            add(metric::omega_rms_z, rms.z());
            add(metric::omega_err_max, std::sqrt(omega_err_sq_max_));
            add(metric::orientation_err_max, orientation_err_max_);
            add(metric::omega_ref_max, std::sqrt(omega_ref_sq_max_));
        }
        if (tracks_energy_drift_) {
            add(metric::energy_drift_max, energy_drift_);
            add(metric::energy_drift_rate, envelope_fit_.slope());
        }
        if (scene_.conserves_angular_momentum())
            add(metric::momentum_drift_max, tracks_momentum_drift_ ? std::sqrt(momentum_change_sq_max_) / momentum0_.norm() : 0.0);
        // |(|q| - 1)| is largest at the largest or the smallest |q|^2 (both start at 1: no error).
        if (probe_)
            for (const auto& [name, value] : probe_->metrics()) r.metrics.emplace_back(name, unstable() ? nan : value);
        add(metric::quat_norm_err_max,
            std::max(std::abs(std::sqrt(quat_norm_sq_max_) - 1.0), std::abs(std::sqrt(quat_norm_sq_min_) - 1.0)));
        if (unstable()) {
            r.metrics.emplace_back(metric::fail_step, static_cast<double>(fail_step_));
            r.metrics.emplace_back(metric::fail_time, fail_time_);
            r.failure = fmt::format("blew up at step {} (t = {:.6g} s)", fail_step_, fail_time_);
        }
        r.series_columns = series_columns_;
        r.series = series_;
        if (probe_ && !unstable()) add_probe_pictures(*probe_, r);
    }

private:
    // Out of line, so that operator() stays small enough to be inlined into the run loop for
    // the scenes without a per-step reference (the fibre: most of the suite's steps).
    [[gnu::noinline]] void compare_with_reference(std::int64_t n, double t, const Bodies& b) {
        for (std::size_t i = 0; i < b.size(); ++i) {
            const ReferenceState ref = reference_->at(i, n, t);
            const Quat q_unit = b.orientation[i].normalized();
            const Vec3 error_body = to_body(q_unit, b.omega[i]) - to_body(ref.q, ref.omega);
            squared_error_sum_ += error_body.cwiseAbs2();
            ++samples_;
            omega_err_sq_max_ = std::max(omega_err_sq_max_, (b.omega[i] - ref.omega).squaredNorm());
            omega_ref_sq_max_ = std::max(omega_ref_sq_max_, ref.omega.squaredNorm());
            orientation_err_max_ = std::max(orientation_err_max_, rotation_angle_between(q_unit, ref.q));
        }
    }

    void record(double t, const Bodies& b) {
        std::vector<double> row = {t, energy0_ != 0.0 ? (scene_.energy(b) - energy0_) / std::abs(energy0_) : nan};
        for (const auto& [name, value] : scene_.energy_parts(b)) row.push_back(value);
        series_.push_back(std::move(row));
    }

    const Scene& scene_;
    const Reference* reference_;
    std::int64_t series_stride_;
    std::int64_t until_record_ = series_stride_;  // steps to the next series sample (a countdown: no division per step)
    // The scene's answers, asked once.
    bool conserves_energy_, gains_energy_;
    double energy0_, energy_scale_, runaway_limit_;
    bool tracks_energy_drift_;
    Vec3 momentum0_;
    bool tracks_momentum_drift_;
    std::unique_ptr<SceneProbe> probe_;
    // Least-squares line through the envelope max_{s<=t} |E(s) - E0|/|E0|: its slope is
    // the secular drift rate (per second), apart from the bounded oscillation.
    struct LineFit {
        double n = 0, st = 0, sy = 0, stt = 0, sty = 0;
        void add(double t, double y) {
            n += 1;
            st += t;
            sy += y;
            stt += t * t;
            sty += t * y;
        }
        double slope() const { return n < 2 ? 0.0 : (n * sty - st * sy) / (n * stt - st * st); }
    } envelope_fit_;
    std::vector<std::string> series_columns_;
    std::vector<std::vector<double>> series_;
    Vec3 squared_error_sum_ = Vec3::Zero();
    std::int64_t samples_ = 0;
    double energy_change_max_ = 0, energy_drift_ = 0, momentum_change_sq_max_ = 0;
    double quat_norm_sq_max_ = 1, quat_norm_sq_min_ = 1, omega_err_sq_max_ = 0, orientation_err_max_ = 0, omega_ref_sq_max_ = 0;
    std::int64_t fail_step_ = 0;
    double fail_time_ = 0;
};

// How a run is timed. A run of at most `whole` steps is timed whole. A longer one is timed
// on a stratified sample: `segments` stretches of `whole / segments` steps, each starting at
// a state the metrics run kept, evenly spaced over the run, with a freshly started scheme.
// Every part of the trajectory (free flight and contact alike) is then timed in proportion,
// so the per-step cost is that of the whole run, for 1e4 steps instead of all of them (a
// second full run of the long ones was a large share of the default suite; larger samples
// gave the same ns_per_step within the run-to-run noise: docs/performance.md).
// (A restarted scheme rebuilds its memory from the state: the same work, different round-off;
// timing never uses the numbers.)
class SampledTiming {
public:
    static constexpr std::int64_t whole = timing_sample_steps, segments = 32;

    explicit SampledTiming(std::int64_t steps) : steps_(steps) {}
    bool sampled() const { return steps_ > whole; }
    std::int64_t segment_steps() const { return sampled() ? whole / segments : steps_; }
    std::int64_t timed_steps() const { return sampled() ? segment_steps() * segments : steps_; }
    // Segment k starts after step floor(k steps / segments), k = 0 ... segments - 1.
    std::int64_t start(std::int64_t k) const { return k * steps_ / segments; }

private:
    std::int64_t steps_;
};

struct Checkpoint {
    std::int64_t step;
    Bodies bodies;
};

// The timing run: the same steps without the observer, so that the reference solution and the
// metrics are not charged to the scheme; a long run's sampled stretches from their checkpoints,
// scaled to the whole run. Warm: the metrics run has just made the same steps (harness/timing.hpp).
CpuTiming timing_run(const Scene& scene, const SchemeFactory& make, double dt, std::int64_t steps, std::vector<Checkpoint> checkpoints) {
    const SampledTiming sampling(steps);
    if (!sampling.sampled()) checkpoints = {{0, scene.initial_state()}};
    CpuTiming cpu = median_cpu_seconds([&] {
        for (const Checkpoint& start : checkpoints) {
            Bodies bodies = start.bodies;
            auto scheme = make();
            std::int64_t evals = 0;
            simulate(
                scene, *scheme, bodies, dt, sampling.segment_steps(), evals,
                [](std::int64_t, double, const Bodies&) { return !interrupt_signal(); }, start.step);
        }
    });
    const double scale = static_cast<double>(steps) / static_cast<double>(sampling.timed_steps());
    for (double& sample : cpu.samples) sample *= scale;
    return {cpu.median * scale, cpu.min * scale, cpu.max * scale, cpu.repeats, cpu.samples};
}

}  // namespace

void add_probe_pictures(const SceneProbe& probe, RunResult& r) {
    // The energy series and a probe's curve never meet (granular scenes are damped): the curve
    // takes the series' place when there is none.
    if (SceneProbe::Curve curve = probe.curve(); !curve.rows.empty() && r.series.empty()) {
        r.series_columns = std::move(curve.columns);
        r.series = std::move(curve.rows);
    }
    SceneProbe::Snapshots pictures = probe.snapshots();
    r.snapshots = std::move(pictures.spheres);
    r.walls = std::move(pictures.walls);
}

std::unique_ptr<Scene> scene_of(const RunSpec& spec) {
    ParamOverrides overrides = spec.params;
    if (spec.t_end > 0.0) overrides.push_back({"t_end", {spec.t_end}});
    return make_scene(spec.scene, overrides);
}

RunResult run_one(const RunSpec& requested, const RunOptions& options) {
    const double start = thread_cpu_seconds();
    RunResult r;
    try {
        switch (requested.kind) {
            case RunKind::reversal: r = run_reversal(requested); break;
            case RunKind::stability: r = run_stability_search(requested); break;
            case RunKind::trajectory: r = run_trajectory(requested, options, registered_scheme(requested.scheme)); break;
            case RunKind::horizon: r = run_horizon(requested, registered_scheme(requested.scheme)); break;
            case RunKind::amplification: r = run_amplification(requested); break;
            case RunKind::spectral: r = run_spectral(requested); break;
            case RunKind::states: r = run_states(requested, options); break;
            case RunKind::cost: r = run_cost(requested, registered_scheme(requested.scheme)); break;
        }
    } catch (const std::bad_alloc&) {  // what the run records (reference, series) outgrew memory: not the scheme's failure
        r = RunResult{requested, {}, {}};
        r.failure = out_of_memory_failure;
        return r;
    }
    if (!r.interrupted) r.metrics.emplace_back(metric::cpu_seconds_run, thread_cpu_seconds() - start);  // all it took
    return r;
}

std::string caught_failure(const std::string& scheme) {
    try {
        throw;
    } catch (const std::exception& e) {
        if (dynamic_cast<const std::bad_alloc*>(&e) && !plugin_of(scheme)) throw;
        return std::string("threw: ") + e.what();
    } catch (...) {
        return "threw an exception that is not a std::exception";
    }
}

SchemeFactory registered_scheme(const std::string& id) { return SchemeRegistry::instance().at(id, "scheme").make; }

RunResult run_trajectory(const RunSpec& requested, const RunOptions& options, const SchemeFactory& make) {
    const auto scene = scene_of(requested);
    RunResult result{requested, {}, {}};
    result.spec.t_end = scene->t_end();
    const double dt = result.spec.dt;
    const std::int64_t steps = step_count(result.spec.t_end, dt);

    std::int64_t force_evals = 0, done = 0;
    bool unstable = false;
    double loop_seconds = nan, rotation_seconds = nan;
    std::vector<Checkpoint> checkpoints;
    try {
        Bodies bodies = scene->initial_state();
        std::unique_ptr<RotationScheme> scheme = make();
        TimedScheme* timed = nullptr;
        if (scene->times_in_run())
            scheme = std::make_unique<TimedScheme>(std::move(scheme)), timed = static_cast<TimedScheme*>(scheme.get());
        const double loop_start = thread_cpu_seconds();
        const auto reference = make_reference(*scene, dt, steps);
        const std::int64_t stride =
            options.series_samples > 0 && scene->reports_energy_series() ? std::max<std::int64_t>(1, steps / options.series_samples) : 0;
        MetricsObserver observer(*scene, reference.get(), bodies, stride);
        const SampledTiming sampling(steps);
        if (sampling.sampled()) checkpoints.push_back({0, bodies});
        // The step at which the next segment starts (none: never reached).
        std::int64_t next_start = sampling.sampled() ? sampling.start(1) : -1;
        done = simulate(*scene, *scheme, bodies, dt, steps, force_evals, [&](std::int64_t n, double t, const Bodies& b) {
            if (n == next_start) {
                checkpoints.push_back({n, b});
                next_start = checkpoints.size() < SampledTiming::segments ? sampling.start(std::ssize(checkpoints)) : -1;
            }
            return observer(n, t, b);
        });
        if (timed) loop_seconds = thread_cpu_seconds() - loop_start, rotation_seconds = timed->seconds();
        observer.write(result);
        unstable = observer.unstable();
    } catch (...) {
        result.failure = caught_failure(requested.scheme);
        unstable = true;
    }

    CpuTiming cpu{nan, nan, nan, 0, {}};
    std::int64_t timed_steps = 0;
    if (!unstable && scene->times_in_run()) {
        timed_steps = done;
        cpu = {loop_seconds, loop_seconds, loop_seconds, 1, {loop_seconds}};
        result.timing_samples = cpu.samples;
        result.metrics.emplace_back(metric::rotation_share, rotation_seconds / loop_seconds);
        result.metrics.emplace_back(metric::cpu_seconds_per_simulated_second, loop_seconds / result.spec.t_end);
    } else if (!unstable && options.measure_time && requested.timed && !interrupt_signal()) {
        timed_steps = SampledTiming(steps).timed_steps();
        cpu = timing_run(*scene, make, dt, steps, checkpoints);
        result.timing_samples = cpu.samples;
    }
    if (interrupt_signal()) {  // the run or its timing was cut short: not a result
        result.interrupted = true;
        return result;
    }
    result.metrics.emplace_back(metric::steps, static_cast<double>(done));
    result.metrics.emplace_back(metric::force_evals, static_cast<double>(force_evals));
    result.metrics.emplace_back(metric::cpu_seconds, cpu.median);
    result.metrics.emplace_back(metric::cpu_seconds_min, cpu.min);
    result.metrics.emplace_back(metric::cpu_seconds_max, cpu.max);
    result.metrics.emplace_back(metric::timing_repeats, cpu.repeats);
    result.metrics.emplace_back(metric::timed_steps, static_cast<double>(timed_steps));
    result.metrics.emplace_back(metric::ns_per_step, cpu.median / static_cast<double>(steps) * 1e9);
    result.metrics.emplace_back(metric::unstable, unstable ? 1.0 : 0.0);
    return result;
}

}  // namespace rotbench
