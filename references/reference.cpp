#include "references/reference.hpp"

#include "references/odeint_reference.hpp"

namespace rotbench {
namespace {

class ClosedFormReference final : public Reference {
public:
    explicit ClosedFormReference(const Scene& scene) : scene_(scene) {}
    ReferenceState at(std::size_t body, std::int64_t, double t) const override { return scene_.exact(body, t); }

private:
    const Scene& scene_;
};

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
        case Scene::ReferenceKind::closed_form: return std::make_unique<ClosedFormReference>(scene);
        case Scene::ReferenceKind::odeint:
            return std::make_unique<SampledReference>(scene, odeint_reference(scene, dt, steps));
        case Scene::ReferenceKind::none: break;
    }
    return nullptr;
}

}  // namespace rotbench
