#include "harness/scenes/scene.hpp"

#include "schemes/quaternion.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <stdexcept>

namespace rotbench {

std::unique_ptr<Scene> make_scene(const std::string& id, const ParamOverrides& overrides) {
    auto scene = SceneRegistry::instance().at(id, "scene").make();
    scene->params.apply(overrides);
    try {
        scene->prepare();
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {  // e.g. a closed form's domain error for extreme values
        throw InputError(id + ": these parameters give no motion rotbench can follow (" + e.what() + ")");
    }
    // Values so large that the energy or the angular momentum overflows would overflow the
    // closed forms and the metrics too: refused here, before anything runs.
    const Bodies b = scene->initial_state();
    const double energy = scene->energy(b), momentum = total_angular_momentum(b).norm();
    if (!(std::abs(energy) <= max_magnitude) || !(momentum <= max_magnitude))
        throw InputError(fmt::format("{}: the initial energy ({:g} J) or angular momentum ({:g} kg m^2/s) is not finite or exceeds "
                                     "{:g}: the parameters overflow what the closed forms and the metrics can hold",
                                     id, energy, momentum, max_magnitude));
    return scene;
}

ReferenceState Scene::exact(std::size_t, double) const {
    throw std::logic_error("this scene has no closed-form solution");
}

double Scene::energy(const Bodies& bodies) const { return kinetic_energy(bodies); }

std::vector<std::pair<std::string, double>> Scene::energy_parts(const Bodies& bodies) const {
    return {{"translational", translational_energy(bodies)}, {"rotational", rotational_energy(bodies)}};
}

std::vector<double> halving_ladder(double dt_max, int rungs, std::vector<double> extra) {
    std::vector<double> dts;
    for (int k = 0; k < rungs; ++k) dts.push_back(std::ldexp(dt_max, -k));  // exact halvings
    for (double dt : extra)
        if (std::find(dts.begin(), dts.end(), dt) == dts.end()) dts.push_back(dt);
    std::sort(dts.begin(), dts.end(), std::greater<>());
    return dts;
}

Vec3 total_angular_momentum(const Bodies& b) {
    Vec3 l = Vec3::Zero();
    for (std::size_t i = 0; i < b.size(); ++i)
        l += momentum_from_omega(b.orientation[i], b.inertia[i], b.omega[i]) +
             b.mass[i] * b.position[i].cross(b.velocity[i]);
    return l;
}

}  // namespace rotbench
