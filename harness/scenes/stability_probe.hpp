// What a scene of the stability study states about itself (harness/exec/stability.hpp
// measures the limits it is compared with).
#pragma once

#include <string>
#include <vector>

namespace rotbench {

class StabilityProbe {
public:
    virtual ~StabilityProbe() = default;
    virtual double predicted_limit() const = 0;  // Peng et al.'s closed form for this scene
    virtual double period() const = 0;           // of its fastest motion; the horizon counts these
    // True where the initial state at rest is an equilibrium about which to linearise.
    virtual bool linearisable_at_rest() const = 0;
};

// The scenes whose type is a StabilityProbe, in the registry's order. Decided by type alone:
// no scene is prepared (a granular scene's grains take seconds to prepare in a sanitizer build).
std::vector<std::string> stability_scene_ids();

}  // namespace rotbench
