// A scene: bodies, initial state, force/torque model, duration, observables and, where it
// has one, a reference solution. A scene models only the physics it needs.
#pragma once

#include "harness/params.hpp"
#include "harness/registry.hpp"
#include "schemes/bodies.hpp"

#include <cstddef>
#include <vector>

namespace rotbench {

struct ReferenceState {
    Quat q;      // body -> world
    Vec3 omega;  // world frame
};

class Scene {
public:
    virtual ~Scene() = default;

    // Declared by the scene's constructor (with `t_end` always), then overridden by the
    // user, then `prepare` validates them (InputError naming the key) and builds what
    // depends on them.
    Params params;
    virtual void prepare() {}

    virtual Bodies initial_state() const = 0;
    double t_end() const { return params.number("t_end"); }
    virtual std::vector<double> default_dts() const = 0;

    // The one force/torque evaluation of a step: fills bodies.force and bodies.torque
    // (world frame) from the current positions, orientations and velocities.
    virtual void evaluate_forces(Bodies& bodies, double t) const = 0;

    virtual bool has_reference() const { return false; }
    virtual ReferenceState reference(std::size_t body, double t) const;

    // Total mechanical energy; the default is the kinetic energy, right for free bodies.
    virtual double energy(const Bodies& bodies) const;
    // True where the total angular momentum is conserved (no external torque).
    virtual bool conserves_angular_momentum() const { return false; }
};

using SceneRegistry = Registry<Scene>;

template <class S>
struct RegisterScene {
    RegisterScene(std::string id, std::string summary, std::string source, std::string notes = "") {
        SceneRegistry::instance().add({id, std::move(summary), std::move(source), std::move(notes), [id] {
                                           auto scene = std::make_unique<S>();
                                           scene->params.set_owner(id);
                                           return scene;
                                       }});
    }
};

// The scene `id` with its parameters overridden and validated (InputError on bad input).
std::unique_ptr<Scene> make_scene(const std::string& id, const ParamOverrides& overrides = {});

double kinetic_energy(const Bodies& bodies);
Vec3 total_angular_momentum(const Bodies& bodies);  // about the origin, world frame

}  // namespace rotbench
