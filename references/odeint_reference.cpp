// GCC 12 reports Odeint's stepper copy constructor as reading uninitialised buffers
// (a false positive; the buffers are resized before use).
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "references/odeint_reference.hpp"

#include "schemes/quaternion.hpp"

#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <limits>
#include <optional>

namespace rotbench {
namespace {

namespace odeint = boost::numeric::odeint;
using State = std::vector<double>;
// Per body: x(3) v(3) q(4) L/I_max(3). The momentum is divided by the body's largest
// principal moment so that it carries the size of w: one absolute tolerance then means the
// same for every component (a fibre's |L| ~ 1e-5 would otherwise be resolved to 1e-8 only).
constexpr std::size_t block = 13;

// The equations of motion of a scene, on a scratch copy of its bodies.
class EquationsOfMotion {
public:
    explicit EquationsOfMotion(const Dynamics& scene) : scene_(scene), bodies_(scene.initial_state()) {}

    State initial() const {
        State y(block * bodies_.size());
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            double* b = &y[block * i];
            const Quat q = bodies_.orientation[i];
            const Vec3 x = bodies_.position[i], v = bodies_.velocity[i];
            const Vec3 l = momentum_from_omega(q, bodies_.inertia[i], bodies_.omega[i]) / momentum_scale(i);
            const double values[block] = {x.x(), x.y(), x.z(), v.x(), v.y(), v.z(), q.w(), q.x(), q.y(), q.z(), l.x(), l.y(), l.z()};
            std::copy(values, values + block, b);
        }
        return y;
    }

    // Writes the state into the scratch bodies; returns them.
    const Bodies& load(const State& y) {
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const double* b = &y[block * i];
            const Quat q(b[6], b[7], b[8], b[9]);
            bodies_.position.set(i, Vec3(b[0], b[1], b[2]));
            bodies_.velocity.set(i, Vec3(b[3], b[4], b[5]));
            bodies_.orientation.set(i, q);
            bodies_.omega.set(i, omega_from_momentum(q, bodies_.inertia[i], momentum_scale(i) * Vec3(b[10], b[11], b[12])));
        }
        return bodies_;
    }

    void operator()(const State& y, State& dy, double t) {
        load(y);
        scene_.evaluate_forces(bodies_, t);
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const double* b = &y[block * i];
            double* d = &dy[block * i];
            const Vec3 a = bodies_.force[i] / bodies_.mass[i], w = bodies_.omega[i];
            const Vec3 tq = bodies_.torque[i] / momentum_scale(i);
            const Quat dq = Quat(0.0, w.x(), w.y(), w.z()) * Quat(b[6], b[7], b[8], b[9]);
            const double values[block] = {b[3], b[4], b[5], a.x(), a.y(), a.z(), 0.5 * dq.w(), 0.5 * dq.x(),
                                          0.5 * dq.y(), 0.5 * dq.z(), tq.x(), tq.y(), tq.z()};
            std::copy(values, values + block, d);
        }
    }

    void record(const State& y, Trajectory& out) {
        load(y);
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const Quat q = bodies_.orientation[i];
            const Vec3 w = bodies_.omega[i], x = bodies_.position[i], v = bodies_.velocity[i];
            out.values.insert(out.values.end(), {q.w(), q.x(), q.y(), q.z(), w.x(), w.y(), w.z(), x.x(), x.y(),
                                                 x.z(), v.x(), v.y(), v.z()});
        }
    }

    std::size_t bodies() const { return bodies_.size(); }
    double momentum_scale(std::size_t i) const { return bodies_.inertia[i].maxCoeff(); }
    std::vector<double> gaps(const State& y) { return scene_.contact_gaps(load(y)); }

private:
    const Dynamics& scene_;
    Bodies bodies_;
};

bool crossed(const std::vector<double>& before, const std::vector<double>& after) {
    for (std::size_t i = 0; i < before.size(); ++i)
        if ((before[i] > 0.0) != (after[i] > 0.0)) return true;
    return false;
}

// A step no longer than half the time any closing gap would take to reach zero at its
// current rate: a contact that starts and ends within one step would show no change of
// sign at the step's ends (a spinning fibre grazes the floor with one sphere).
double approach_limit(const std::vector<double>& before, const std::vector<double>& after, double step) {
    double limit = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < before.size(); ++i)
        if (after[i] > 0.0 && after[i] < before[i]) limit = std::min(limit, 0.5 * after[i] * step / (before[i] - after[i]));
    return limit;
}

// Controlled integration that lands on each sample time and on each change of sign of a
// contact gap. When an accepted step has crossed one, the crossing time is located by
// bisection on single Fehlberg steps from the step's start (to 1e-15 s), and the
// controlled integration goes back and runs to that time on steps that halve what is left
// (a graded mesh), then on from there with a tiny first step. Without this the Hertz force,
// whose derivatives blow up at contact onset and exit ((t - t0)^3.5 in the solution),
// fools the error estimate: energy errors of 1e-5 at tolerance 1e-13 on `fibre_bounce`,
// and 1e-8 from a single accepted step that ends at a contact exit.
template <class Controlled>
void integrate_with_events(Controlled& controlled, EquationsOfMotion& system, State& y, const std::vector<double>& times,
                           Trajectory& out, const std::function<bool()>& keep_going) {
    auto rhs = [&](const State& s, State& d, double t) { system(s, d, t); };
    odeint::runge_kutta_fehlberg78<State> probe;
    const double restart_step = 1e-10 * (times.back() - times.front());
    double t = times.front(), h = times.size() > 1 ? times[1] - times[0] : 1e-3;
    std::optional<double> event;  // a located crossing, not yet reached
    system.record(y, out);
    std::vector<double> gaps = system.gaps(y);
    // A budget of steps: a hundred a sample (the stiffest scene here takes a few) and 100,000
    // more for the contact events; past it the scene is too stiff or too ill-scaled for a
    // reference in bounded time (advise --mass 1e-300 ran for hours).
    const auto budget = 100000LL + 100LL * static_cast<long long>(times.size());
    long long attempts = 0;
    for (std::size_t k = 1; k < times.size(); ++k) {
        while (t < times[k]) {
            if (++attempts > budget)
                throw std::runtime_error("Odeint reference: more than " + std::to_string(budget) + " steps for " + std::to_string(times.size()) +
                                         " samples (a scene too stiff or too ill-scaled for its reference)");
            if (attempts % 1024 == 0 && keep_going && !keep_going()) throw std::runtime_error("Odeint reference: stopped");
            const double target = event && *event < times[k] ? *event : times[k];
            // Toward a located crossing the steps are graded: each covers at most half of
            // what is left, so no step ends on the singularity with a large size.
            const double cap = event && target == *event && target - t > 2.0 * restart_step ? 0.5 * (target - t) : h;
            const bool to_target = std::min(h, cap) >= target - t;
            double step = to_target ? target - t : std::min(h, cap);
            const State y0 = y;
            const double t0 = t;
            if (controlled.try_step(rhs, y, t, step) != odeint::success) {
                h = step;  // rejected: the stepper proposed a smaller one
                continue;
            }
            if (to_target) t = target;  // exactly, not t0 + (target - t0) in floating point
            h = to_target ? std::max(h, step) : step;
            const std::vector<double> next_gaps = system.gaps(y);
            if (event && to_target && target == *event) {  // arrived at the located crossing
                event.reset();
                gaps = next_gaps;
                h = restart_step;
                continue;
            }
            if (event || gaps.empty() || !crossed(gaps, next_gaps)) {
                if (!gaps.empty()) h = std::max(std::min(h, approach_limit(gaps, next_gaps, t - t0)), restart_step);
                gaps = next_gaps;
                continue;
            }
            double lo = 0.0, hi = t - t0;
            while (hi - lo > 1e-15) {
                const double mid = 0.5 * (lo + hi);
                State trial = y0;
                probe.do_step(rhs, trial, t0, mid);
                (crossed(gaps, system.gaps(trial)) ? hi : lo) = mid;
            }
            event = t0 + hi;  // go back and integrate up to it under error control
            y = y0;
            t = t0;
            h = hi;
        }
        system.record(y, out);
    }
}

}  // namespace

Trajectory integrate_scene(const Dynamics& scene, const std::vector<double>& times, OdeMethod method, double tolerance,
                           const std::function<bool()>& keep_going) {
    EquationsOfMotion system(scene);
    Trajectory out;
    out.bodies = system.bodies();
    out.values.reserve(times.size() * out.bodies * Trajectory::width);
    State y = system.initial();
    // Error relative to the state only (a_x = 1, a_dxdt = 0): Odeint's default also scales
    // the tolerance by dt |dx/dt|, which loosens it exactly where a contact changes the
    // state fast (10x and more in a Hertz contact).
    if (method == OdeMethod::fehlberg78) {
        using Stepper = odeint::runge_kutta_fehlberg78<State>;
        odeint::controlled_runge_kutta<Stepper> stepper(
            odeint::default_error_checker<double, Stepper::algebra_type, Stepper::operations_type>(tolerance, tolerance, 1.0, 0.0));
        integrate_with_events(stepper, system, y, times, out, keep_going);
    } else {
        odeint::bulirsch_stoer<State> stepper(tolerance, tolerance, 1.0, 0.0);
        integrate_with_events(stepper, system, y, times, out, keep_going);
    }
    return out;
}

std::vector<double> equally_spaced_times(double t_end, int samples) {
    std::vector<double> times(static_cast<std::size_t>(samples) + 1);
    for (int k = 0; k <= samples; ++k) times[k] = t_end * k / samples;
    return times;
}

CrossCheck cross_check(const Dynamics& scene, double t_end, int samples, double tolerance) {
    const std::vector<double> times = equally_spaced_times(t_end, samples);
    const Trajectory a = integrate_scene(scene, times, OdeMethod::fehlberg78, tolerance);
    const Trajectory b = integrate_scene(scene, times, OdeMethod::bulirsch_stoer, tolerance);
    double omega_scale = 0, position_scale = 0;
    for (std::size_t s = 0; s < a.samples(); ++s)
        for (std::size_t i = 0; i < a.bodies; ++i) {
            omega_scale = std::max(omega_scale, a.state(s, i).omega.norm());
            position_scale = std::max(position_scale, a.position(s, i).norm());
        }
    CrossCheck c;
    for (std::size_t s = 0; s < a.samples(); ++s)
        for (std::size_t i = 0; i < a.bodies; ++i) {
            const ReferenceState x = a.state(s, i), y = b.state(s, i);
            c.omega_relative = std::max(c.omega_relative, (x.omega - y.omega).norm() / std::max(omega_scale, 1e-300));
            c.angle = std::max(c.angle, rotation_angle_between(x.q.normalized(), y.q.normalized()));
            c.position = std::max(c.position, (a.position(s, i) - b.position(s, i)).norm() / std::max(position_scale, 1.0));
        }
    return c;
}

}  // namespace rotbench
