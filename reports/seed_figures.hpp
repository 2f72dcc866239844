// What the seed's Figures 9-11 (Irazabal et al., test case 2, the bouncing fibre) show,
// as data: the schemes ordered by their energy error at the end of the run, best first.
#pragma once

#include <string>
#include <vector>

namespace rotbench {

struct PublishedEnergyOrdering {
    std::string scene;
    double dt;
    std::vector<std::string> best_to_worst;  // rotbench ids; one id: "this one is the best"
    std::string statement;                   // the seed's words, paraphrased
};

inline const std::vector<PublishedEnergyOrdering>& seed_energy_orderings() {
    static const std::vector<PublishedEnergyOrdering> orderings = {
        {"fibre_bounce", 1e-7, {"zvw_corrected", "zvw", "munjiza_rk4", "direct"},
         "Figs. 9-10 (dt = 1e-7): the energy error of direct reaches almost 0.4 % at the end, Runge-Kutta stays "
         "below 0.1 %, Zhao-van Wachem lower still, and the corrected Zhao-van Wachem is better than the original"},
        {"fibre_bounce", 1e-5, {"zvw_corrected"},
         "Fig. 11 (dt = 1e-5): the superiority of the (corrected) quaternion scheme can be clearly appreciated"},
    };
    return orderings;
}

}  // namespace rotbench
