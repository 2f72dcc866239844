#include "harness/exec/reference.hpp"

#include "harness/exec/interrupt.hpp"
#include "harness/exec/shared_trajectory.hpp"
#include "harness/store/reference_cache.hpp"
#include "references/odeint_reference.hpp"

#include <fmt/format.h>

namespace rotbench {
namespace {

// The closed form evaluated at every step t_k = k dt, once for all the schemes of a sweep
// (harness/exec/shared_trajectory.hpp): the same values for every scheme, and elliptic
// integrals are dear.
class ClosedFormReference final : public Reference {
public:
    ClosedFormReference(const Scene& scene, double dt, std::int64_t steps) {
        const std::string key = fmt::format("closed-form|{}|dt={}|steps={}|{}", scene.params.owner(), dt, steps,
                                            scene.params.canonical());
        trajectory_ = shared_trajectory(key, [&] {
            Trajectory t;
            t.bodies = scene.initial_state().size();
            t.values.resize(static_cast<std::size_t>(steps + 1) * t.bodies * Trajectory::width);
            for (std::int64_t k = 0; k <= steps; ++k)
                for (std::size_t body = 0; body < t.bodies; ++body) {
                    const ReferenceState s = scene.exact(body, static_cast<double>(k) * dt);  // t as the run loop
                    double* v = &t.values[(static_cast<std::size_t>(k) * t.bodies + body) * Trajectory::width];
                    v[0] = s.q.w(), v[1] = s.q.x(), v[2] = s.q.y(), v[3] = s.q.z();
                    v[4] = s.omega.x(), v[5] = s.omega.y(), v[6] = s.omega.z();
                }
            return t;
        });
    }
    ReferenceState at(std::size_t body, std::int64_t step, double) const override {
        return trajectory_->state(static_cast<std::size_t>(step), body);
    }

private:
    std::shared_ptr<const Trajectory> trajectory_;
};

// The Odeint reference at t_k = k dt, k = 0..steps, by Fehlberg 7(8). Computed once per scene,
// parameters, dt and steps: kept in memory for the process and on disk between runs
// (harness/store/reference_cache.hpp).
std::shared_ptr<const Trajectory> odeint_reference(const Scene& scene, double dt, std::int64_t steps) {
    const std::string key = fmt::format("odeint-fehlberg78|tol={}|dt={}|steps={}|{}", reference_tolerance, dt, steps,
                                        scene.params.canonical());
    return shared_trajectory(key, [&] {
        const std::string& scene_id = scene.params.owner();
        if (auto cached = load_cached(scene_id, key)) return std::move(*cached);
        std::vector<double> times(static_cast<std::size_t>(steps) + 1);
        for (std::size_t k = 0; k < times.size(); ++k) times[k] = static_cast<double>(k) * dt;  // as the run loop
        Trajectory trajectory =
            integrate_scene(scene, times, OdeMethod::fehlberg78, reference_tolerance, [] { return !interrupt_signal(); });
        store_cached(scene_id, key, trajectory);
        return trajectory;
    });
}

class SampledReference final : public Reference {
public:
    SampledReference(const Scene& scene, std::shared_ptr<const Trajectory> trajectory)
        : scene_(scene), trajectory_(std::move(trajectory)) {}
    ReferenceState at(std::size_t body, std::int64_t step, double t) const override {
        ReferenceState s = trajectory_->state(static_cast<std::size_t>(step), body);
        if (const auto w = scene_.exact_omega_body(body, t)) s.omega = s.q.normalized() * *w;
        return s;
    }

private:
    const Scene& scene_;
    std::shared_ptr<const Trajectory> trajectory_;
};

}  // namespace

std::unique_ptr<Reference> make_reference(const Scene& scene, double dt, std::int64_t steps) {
    switch (scene.reference_kind()) {
        case Scene::ReferenceKind::closed_form: return std::make_unique<ClosedFormReference>(scene, dt, steps);
        case Scene::ReferenceKind::odeint:
            return std::make_unique<SampledReference>(scene, odeint_reference(scene, dt, steps));
        case Scene::ReferenceKind::none: break;
    }
    return nullptr;
}

}  // namespace rotbench
