// What the runs say of each scheme, against what it claims: the figures behind the report's
// verdict table and its recommendation. The judges are the claims module's (claims.hpp), so
// the report cannot call "kept" or "bounded" what the gate fails.
#pragma once

#include "harness/analysis/orders.hpp"
#include "harness/analysis/result_set.hpp"
#include "harness/analysis/stability_study.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace rotbench {

// The observed order of the angular-velocity error over the judged scenes of one kind
// (torque-free with a reference, or under an orientation-dependent torque).
struct OrderVerdict {
    std::string claimed = "—";  // "—", "exact" or the claimed order
    int claimed_order = 0;
    double lo = NAN, hi = NAN;  // over the scenes whose order was fitted
    int fitted = 0, exact = 0, insufficient = 0, no_convergence = 0;
    double stuck_lo = NAN, stuck_hi = NAN;  // relative error at the finest step where it does not converge
    int scenes() const { return fitted + exact + insufficient + no_convergence; }
};

enum class EnergyVerdict { none, kept, bounded, drifting, not_judged };

struct SchemeVerdict {
    std::string scheme;
    bool control = false;  // sound = false
    OrderVerdict free, torque;
    int momentum_runs = 0;  // torque-free runs judged
    bool momentum_kept = false;
    double momentum_worst = 0;
    EnergyVerdict energy = EnergyVerdict::none;
    double energy_bounded_max = 0, energy_growth = 0;  // the largest error over the horizon; the largest growth
    std::string energy_failed;                          // scenes whose horizon run failed
    double stability_lo = NAN, stability_hi = NAN;      // measured limit / Peng's over the contact pairs
    std::string stability_weak, stability_failed;       // "scene ζ = z" lists
    // Its claims (SchemeClaims) judged as the gate judges them, on the runs there are: "" when
    // every judged claim holds, else the claims that fail, "claim on scene"; claims_judged counts
    // the judgements made (0: nothing claimed, or nothing here to judge it on).
    std::vector<std::string> claims_failed;
    int claims_judged = 0;
    bool claims_anything = false;  // it registers a claim at all (an order, exactness, momentum, energy)
    bool claims_bounded_energy = false;  // whether it claims bounded energy at all
    double ns_per_step = NAN;                            // the report's cost figure, on cost_scene()
    // A client's own cost on cost_scene(), never ranked with ns_per_step: its program's wall time per
    // step with the start-up removed, from two lengths of one run (the horizon run, 8 T at the
    // coarsest dt, less the trajectory run of T at that dt).
    double client_wall_ns_per_step = NAN;
};

// The scene whose ns_per_step is the report's cost figure: asymmetric_free, or else the first
// single-body scene of the runs.
std::string cost_scene(const ResultSet& set);

// One per scheme of the runs, in their order.
std::vector<SchemeVerdict> scheme_verdicts(const ResultSet& set, const std::vector<OrderRow>& orders,
                                           const std::vector<StabilityRow>& stability);

// A client against the built-in scheme it should equal, on one scene: the same map (its runs
// differ from the counterpart's by round-off only, at every dt) or another one, whose
// difference falls as dt^order between the coarsest and the finest dt.
struct CounterpartVerdict {
    std::string client, counterpart, scene;
    const RunResult* coarse = nullptr;  // its runs at the coarsest and the finest dt
    const RunResult* fine = nullptr;
    bool same_map = false;
    double order = NAN;
    std::string note;  // the client file's reason where it is not the same map
    static double relative(const RunResult& r);  // max |Δw| / |w_ref|
};
std::vector<CounterpartVerdict> counterpart_verdicts(const ResultSet& set);

// Below this fraction of Peng's step, a scheme's stability limit rules it out for contacts.
inline constexpr double weak_stability_ratio = 0.1;

// Which schemes to use and which to avoid, and why, from the verdicts alone (the report's
// recommendation).
struct SchemeChoice {
    // Claims second order with and without torque and meets its claims (as the gate judges
    // them), momentum kept, energy bounded, no weak stability; cheapest first.
    std::vector<std::string> use;
    // The same, but energy drifting: for short runs; cheapest first.
    std::vector<std::string> short_runs;
    std::vector<std::pair<std::string, std::string>> avoid;  // scheme, why
    // None of its claims judged here (no run on the scenes that judge them): neither.
    std::vector<std::string> unjudged;
    // Under damping (ζ > 0): each damping ratio at which, on some contact pair, no sound
    // scheme is stable at Peng's step; the scene where the best falls shortest, and its ratio.
    struct Unsafe {
        double zeta;
        std::string scene;
        double best_ratio;
    };
    std::vector<Unsafe> peng_unsafe;
};
SchemeChoice recommend(const std::vector<SchemeVerdict>& verdicts, const std::vector<StabilityRow>& stability);

}  // namespace rotbench
