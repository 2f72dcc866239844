// `rotbench stability`: every selected scheme on every selected contact scene and damping
// ratio; the measured limit, the eigenvalue limit and Peng et al.'s prediction.
#pragma once

#include "harness/analysis/stability.hpp"
#include "harness/io/progress.hpp"

#include <cstddef>
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

// Contact scenes run once per zeta, fast_spin once per omega_max; the eigenvalue limit is
// NaN where the scene's state is not an equilibrium at rest.
// InputError unless every id is a scene with a stability probe (the valid ones listed).
void check_stability_scenes(const std::vector<std::string>& scenes);

// A plug-in scheme's case runs in a worker process under these limits (harness/engine/isolation.hpp):
// one that crashes, hangs or exhausts memory fails its own case, the rest go on.
struct StabilityLimits {
    double seconds = 600;      // wall time of one case (or of one scheme's spectral curve)
    std::size_t megabytes = 0; // 0: isolation_memory(jobs)
};

// `progress`, when given, hears of every case as it starts and ends (harness/io/progress.hpp).
std::vector<StabilityRow> stability_study(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                                          const std::vector<double>& zetas, const std::vector<double>& omegas, int jobs,
                                          Progress* progress = nullptr, const StabilityLimits& limits = {});
// How many cases stability_study runs for these inputs (progress counts them).
std::size_t stability_case_count(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                                 const std::vector<double>& zetas, const std::vector<double>& omegas);

// The spectral radius of each scheme's step map against dt, undamped, for each contact scene
// among `scenes` that can be linearised at rest: 41 steps from 1/30 to 3 times Peng's prediction.
struct SpectralCurve {
    std::string scene, scheme;
    double dt_peng = 0;
    std::vector<std::pair<double, double>> points;  // (dt, rho)
    std::string failure;
};
// A curve whose scheme failed in its worker has no points and names why.
std::vector<SpectralCurve> spectral_radius_curves(const std::vector<std::string>& scenes, const std::vector<std::string>& schemes,
                                                  const StabilityLimits& limits = {});

// What the worker of one case does (`rotbench __stability`), in process: the row's limits,
// or one scheme's spectral curve on a scene, each written as text for run_worker's caller.
void measure_stability_case(StabilityRow& row);
std::string stability_case_text(const StabilityRow& row);
std::string spectral_curve_text(const std::string& scene, const std::string& scheme);

}  // namespace rotbench
