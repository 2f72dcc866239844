// A client's run on a contact scene (sphere_pair, ellipsoid_pair): the program gets both
// bodies and the contact law in physical terms and returns both bodies' states at every step;
// rotbench computes every metric, and the stability criterion, from those states as it does
// for a built-in run (docs/clients.md, "Contact scenes").
#pragma once

#include "harness/exec/client_trajectory.hpp"
#include "harness/exec/stability.hpp"
#include "harness/core/run.hpp"
#include "harness/scenes/contact_pair.hpp"
#include "schemes/scheme.hpp"

#include <memory>
#include <string>
#include <vector>

namespace rotbench {

// The scene's spec as a contact client reads it, for a run of `steps` steps of `dt`.
std::string contact_scene_json(const ContactPairScene& scene, const RunSpec& spec, double t_end, std::int64_t steps);

// The program's states stepped through as if a scheme made them: each step ends on the next
// rows, whatever the harness's own translation step did before.
std::unique_ptr<RotationScheme> contact_replay(const std::vector<TrajectoryRow>& rows);

// The stability criterion on the program's states (harness/exec/stability.hpp): the energy of
// some step past `growth` times the initial state's, or not finite.
bool contact_blew_up(const ContactPairScene& scene, const std::vector<TrajectoryRow>& rows, const StabilityCriterion& criterion);

}  // namespace rotbench
