// The stability study's CSV files.
#pragma once

#include "harness/analysis/stability_study.hpp"

#include <string>
#include <vector>

namespace rotbench {

// stability.csv: scene,scheme,zeta,dt_empirical,dt_amplification,dt_peng, one row per contact
// scene, scheme and zeta. The spin sweep, keyed by w_max (which that file has no column for),
// goes to stability_spin.csv: scene,scheme,omega_max,dt_empirical,dt_peng.
std::string stability_csv(const std::vector<StabilityRow>& rows);
std::string stability_spin_csv(const std::vector<StabilityRow>& rows);

}  // namespace rotbench
