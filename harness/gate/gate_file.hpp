// Gate files (docs/gate.md): the claims section, checks, and expected failures.
//
//   [claims]                       # every scheme held to what it registers (SchemeClaims)
//   schemes = ["*"]                # "*": every registered scheme, plug-ins and controls included
//   free    = ["asymmetric_free", "tumbling_brick"]   # torque-free scenes with a reference
//   torque  = ["dipole_top"]       # scenes with an orientation-dependent torque
//   [claims.tumbling_brick]        # optional, for a scene of those lists: its claims' ladder
//   dt = [0.01, 0.005, 0.0025]     # (at least 3 steps; the coarsest is also the bounded-energy
//   params = { ... }               # and reversal runs' step) and scene parameters
//
//   [[check]]                      # one criterion on one scene for a list of schemes
//   name      = "..."              # optional; the check's id in summaries and expected failures
//   scene     = "asymmetric_free"
//   schemes   = ["*"]              # "*": every registered sound scheme, plug-ins included
//   except    = ["exact_splitting"]  # optional, with "*": schemes left out
//   min_order = 0.8                # or max_error, max_energy_drift, max_momentum_drift,
//                                  # min_stability, max_cost_ratio; or same_map_as = "richardson"
//                                  # (clients whose counterpart it is, a built-in or another
//                                  # client: the same map to round-off)
//   metric, dt, t_end, params, round_off, why   (optional)
//
//   [[expected_failure]]           # one check on one (scene, scheme) that is expected to fail
//   check  = "..."                 # a [[check]]'s name or a claim id (order_without_torque, ...)
//   scene  = "..."
//   scheme = "..."
//   reason = "..."
#pragma once

#include "harness/scenes/params.hpp"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace rotbench {

struct GateCheck {
    std::string name;
    std::string scene;
    std::vector<std::string> schemes;
    std::string criterion;  // min_order, max_error, max_energy_drift, max_momentum_drift, min_stability, max_cost_ratio,
                            // same_map_as
    double bound = 0;
    std::string same_map_as;  // same_map_as: the built-in scheme or client every client of the check should equal
    std::string metric;       // the metric the criterion reads
    std::vector<double> dts;  // empty: the scene's ladder (min_order)
    double t_end = 0;
    double round_off = 1e-10;
    ParamOverrides params;
    std::string why;
    std::string location;  // file:line of the [[check]]
};

// What [claims.SCENE] sets for the claims judged on that scene.
struct ClaimScene {
    std::vector<double> dts;  // empty: the scene's ladder
    ParamOverrides params;
};

struct ClaimsSection {
    bool present = false;
    std::vector<std::string> schemes;
    std::vector<std::string> free_scenes, torque_scenes;
    std::map<std::string, ClaimScene> scenes;
    std::string location;
};

struct ExpectedFailure {
    std::string check, scene, scheme, reason, location;
};

struct GateFile {
    std::string path;
    std::string hash;  // FNV-1a of its bytes, hex: which gate file judged, in summary.json and JUnit
    ClaimsSection claims;
    std::vector<GateCheck> checks;
    std::vector<ExpectedFailure> expected_failures;
    std::vector<std::string> warnings;  // schemes the file names that are skipped (see load_gate)
};

// The claim checks a [claims] section makes, by id (what an [[expected_failure]] may name).
const std::vector<std::string>& claim_ids();

// The gate for `schemes` only (`rotbench gate --schemes`): the claims and checks of the other
// schemes, and their expected failures, left out. A check left without a scheme goes.
GateFile only_schemes(GateFile file, const std::vector<std::string>& schemes);

// Reads and checks a gate file; every error names file, line and column (InputError). With
// `only` (gate --schemes), a scheme the file names that is not loaded and not in `only` is left
// out with a warning instead of refused: a clients' gate can judge one client file of several.
GateFile load_gate(const std::string& path, const std::vector<std::string>& only = {});
// The same for text already read; `name` stands for the file in messages.
GateFile parse_gate(std::string_view text, const std::string& name, const std::vector<std::string>& only = {});

}  // namespace rotbench
