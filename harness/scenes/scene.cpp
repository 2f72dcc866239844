#include "harness/scenes/scene.hpp"

#include "schemes/quaternion.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace rotbench {

std::unique_ptr<Scene> make_scene(const std::string& id, const ParamOverrides& overrides) {
    auto scene = SceneRegistry::instance().at(id, "scene").make();
    scene->params.apply(overrides);
    scene->prepare();
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
