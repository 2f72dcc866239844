// `rotbench stability`: every selected scheme on every selected contact scene and damping
// ratio; the measured limit, the eigenvalue limit and Peng et al.'s prediction, and the
// spectral radius of each scheme's step map against dt. Every scheme's work is a run
// (kinds stability, amplification, spectral) made by the executor and kept in the run store.
#pragma once

#include "harness/core/run.hpp"

#include <string>
#include <utility>
#include <vector>

namespace rotbench {

struct StabilityRow {
    std::string scene, scheme;
    double zeta = 0;       // contact scenes
    double omega_max = 0;  // fast_spin
    double dt_empirical = 0, dt_amplification = 0, dt_peng = 0, dt_verlet_normal = 0;
    bool unstable_at_every_dt = false;  // rho > 1 + 1e-6 already at dt_peng / 100
    std::string failure;                // why the case has no result (a plug-in that crashed, hung or threw); the dts are NaN
};

// How a scheme loses stability on the row's scene (stability.csv's `kind`):
//   sharp  stable below a limit, unstable above it;
//   weak   unstable at every dt, its limit only where the gain over the horizon reaches the
//          criterion (rho > 1 however small dt, or no stable dt found at all);
//   none   no limit found up to 2^30 times the first guess;
//   failed the case did not finish (StabilityRow::failure).
std::string stability_kind(const StabilityRow& row);

// InputError unless every id is a scene with a stability probe (the valid ones listed).
void check_stability_scenes(const std::vector<std::string>& scenes);

// The spectral radius of a scheme's step map against dt, undamped, on a contact scene that
// can be linearised at rest (harness/exec/run_kinds.hpp, run_spectral).
struct SpectralCurve {
    std::string scene, scheme;
    double dt_peng = 0;
    std::vector<std::pair<double, double>> points;  // (dt, rho); none when the run failed
    std::string failure;
};

struct StabilityStudy {
    std::vector<StabilityRow> rows;
    std::vector<SpectralCurve> curves;
};

// The study's store in an output folder: its runs, one record each (harness/store/run_record.hpp),
// from which `report` builds the study again; stability.csv and stability_spin.csv are exports.
inline constexpr const char* stability_store = "stability.jsonl";

// The study's runs: contact scenes once per zeta, fast_spin once per omega_max, each scheme
// searched (kind stability) and, where the scene linearises at rest, its eigenvalue limit
// (amplification); then the undamped spectral curves (spectral). A client has no step map to
// linearise: it is searched only, on the scenes its file lists (each pair skipped is said in
// `skipped`, when given).
std::vector<RunSpec> stability_plan(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                                    const std::vector<double>& zetas, const std::vector<double>& omegas,
                                    std::vector<std::string>* skipped = nullptr);

// The study those runs make, rows and curves in their order; the eigenvalue limit is NaN where
// the scene's state is not an equilibrium at rest. InputError (naming `name`) for a run no
// stability_plan makes, or one made twice: a store that was edited.
StabilityStudy stability_study(const std::vector<RunResult>& runs, const std::string& name);

}  // namespace rotbench
