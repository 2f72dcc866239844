// Implementation of rotbench::simulate (included by run.hpp).
#include "schemes/velocity_verlet_translation.hpp"

namespace rotbench {

template <class Observer>
std::int64_t simulate(const Scene& scene, RotationScheme& scheme, Bodies& bodies, double dt, std::int64_t steps,
                      std::int64_t& force_evals, Observer&& observe) {
    scene.evaluate_forces(bodies, 0.0);
    ++force_evals;
    scheme.start(bodies);
    for (std::int64_t n = 1; n <= steps; ++n) {
        const double t = static_cast<double>(n) * dt;
        translation_predict(bodies, dt);
        scheme.predict(bodies, dt);
        scene.evaluate_forces(bodies, t);
        ++force_evals;
        translation_correct(bodies, dt);
        scheme.correct(bodies, dt);
        if (!observe(n, t, bodies)) return n;
    }
    return steps;
}

}  // namespace rotbench
