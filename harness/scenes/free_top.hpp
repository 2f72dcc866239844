// The scaffolding shared by the torque-free single-body scenes (`asymmetric_free`,
// `dzhanibekov`): one body, no force, the closed-form FreeRigidBody as the reference.
// A scene declares its parameters and says how to read the initial angular velocity.
#pragma once

#include "harness/scenes/scene.hpp"
#include "harness/scenes/single_body.hpp"
#include "schemes/detail/free_rigid_body.hpp"

#include <optional>

namespace rotbench {

class FreeTopScene : public Scene {
public:
    static constexpr SceneTraits traits{.reference = ReferenceKind::closed_form, .conserves_angular_momentum = true};
    Bodies initial_state() const override { return single_body(1.0, inertia_, q0_, omega0_body_); }
    void evaluate_forces(Bodies& b, double) const override {
        b.force.set(0, Vec3::Zero());
        b.torque.set(0, Vec3::Zero());
    }
    ReferenceState exact(std::size_t, double t) const override { return {exact_->orientation(t), exact_->omega_world(t)}; }
    std::optional<TorqueLaw> torque_law() const override { return TorqueLaw{}; }

protected:
    // Called by the scene's prepare() once it has read its parameters.
    void set_motion(const Vec3& inertia, const Quat& q0, const Vec3& omega0_body) {
        params.positive("t_end");
        inertia_ = inertia;
        q0_ = q0;
        omega0_body_ = omega0_body;
        exact_.emplace(inertia, q0, omega0_body);
    }

private:
    Vec3 inertia_, omega0_body_;
    Quat q0_;
    std::optional<FreeRigidBody> exact_;
};

}  // namespace rotbench
