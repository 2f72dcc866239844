// The reference a run is compared with, step by step: the scene's closed form, or its
// Odeint trajectory sampled at the run's own steps.
#pragma once

#include "harness/scenes/scene.hpp"

#include <cstdint>
#include <memory>

namespace rotbench {

class Reference {
public:
    virtual ~Reference() = default;
    virtual ReferenceState at(std::size_t body, std::int64_t step, double t) const = 0;
};

// nullptr when the scene has no reference.
std::unique_ptr<Reference> make_reference(const Scene& scene, double dt, std::int64_t steps);

}  // namespace rotbench
