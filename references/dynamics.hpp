// What a reference needs from a scene, and what it gives back. The Odeint engine integrates
// any `Dynamics`: the scene's bodies, its one force/torque model and the gaps of its contacts
// (harness/scenes/scene.hpp derives every scene from it).
#pragma once

#include "schemes/bodies.hpp"

#include <vector>

namespace rotbench {

// The reference's state of one body at one time.
struct ReferenceState {
    Quat q;      // body -> world
    Vec3 omega;  // world frame
};

class Dynamics {
public:
    virtual ~Dynamics() = default;
    virtual Bodies initial_state() const = 0;
    // Fills bodies.force and bodies.torque (world frame) from the current state.
    virtual void evaluate_forces(Bodies& bodies, double t) const = 0;
    // Signed gaps of the contacts the force model can switch on (> 0: apart). Where a gap
    // changes sign the forces are not smooth, and the Odeint reference lands a step there.
    virtual std::vector<double> contact_gaps(const Bodies&) const { return {}; }
};

}  // namespace rotbench
