// A scene: bodies, initial state, force/torque model, duration, observables and, where it
// has one, a reference solution. A scene models only the physics it needs.
#pragma once

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

    virtual Bodies initial_state() const = 0;
    virtual double default_t_end() const = 0;
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
        SceneRegistry::instance().add({std::move(id), std::move(summary), std::move(source), std::move(notes),
                                       [] { return std::make_unique<S>(); }});
    }
};

double kinetic_energy(const Bodies& bodies);
Vec3 total_angular_momentum(const Bodies& bodies);  // about the origin, world frame

}  // namespace rotbench
