// The stability study's CSV files: exports of its runs (stability.jsonl), never read back.
#pragma once

#include "harness/analysis/stability_study.hpp"

#include <string>
#include <vector>

namespace rotbench {

// stability.csv: scene,scheme,zeta,kind,dt_empirical,dt_amplification,dt_peng,dt_verlet_normal,
// one row per contact scene, scheme and zeta. The spin sweep, keyed by w_max (which that file
// has no column for), goes to stability_spin.csv: scene,scheme,omega_max,kind,dt_empirical,dt_peng.
// `kind` is stability_kind(): sharp, weak or none.
std::string stability_csv(const std::vector<StabilityRow>& rows);
std::string stability_spin_csv(const std::vector<StabilityRow>& rows);

}  // namespace rotbench
