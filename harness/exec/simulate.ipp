// Implementation of rotbench::simulate (included by run.hpp).
#include "harness/exec/translation.hpp"

namespace rotbench {

inline void dem_step(const Scene& scene, RotationScheme& scheme, Bodies& bodies, double dt, double t) {
    translation_predict(bodies, dt);
    scheme.predict(bodies, dt);
    scene.evaluate_forces(bodies, t);
    translation_correct(bodies, dt);
    scheme.correct(bodies, dt);
}

template <class Observer>
std::int64_t simulate(const Scene& scene, RotationScheme& scheme, Bodies& bodies, double dt, std::int64_t steps,
                      std::int64_t& force_evals, Observer&& observe, std::int64_t first_step) {
    scene.evaluate_forces(bodies, static_cast<double>(first_step) * dt);
    ++force_evals;
    scheme.start(bodies);
    for (std::int64_t n = first_step + 1; n <= first_step + steps; ++n) {
        const double t = static_cast<double>(n) * dt;
        dem_step(scene, scheme, bodies, dt, t);
        ++force_evals;
        if (!observe(n, t, bodies)) return n;
    }
    return first_step + steps;
}

}  // namespace rotbench
