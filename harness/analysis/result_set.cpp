#include "harness/analysis/result_set.hpp"

namespace rotbench {

SceneInfo scene_info(const Scene& scene) {
    const auto& entry = SceneRegistry::instance().at(scene.params.owner(), "scene");
    SceneInfo info{entry.id,
                   entry.summary,
                   entry.source,
                   entry.notes,
                   scene.reference_kind(),
                   scene.conserves_energy(),
                   scene.conserves_angular_momentum(),
                   scene.torque_depends_on_orientation(),
                   scene.initial_state().size()};
    info.stability_scene = scene.scene_traits().stability;
    for (const auto& p : scene.params.entries())
        if (p.key == "zeta" && p.value.size() == 1) info.zeta = p.value.front();
    return info;
}

ResultSet describe(std::vector<RunResult> runs, const SchemeInfos& recorded) {
    ResultSet set;
    std::vector<std::string> schemes;
    for (const auto& r : runs) schemes.push_back(r.spec.scheme);
    set.schemes = describe_schemes(schemes, recorded);
    for (auto& r : runs) {
        if (!set.scenes.count(r.spec.scene)) set.scenes[r.spec.scene] = scene_info(*make_scene(r.spec.scene, r.spec.params));
        (r.declined() ? set.declined : r.spec.kind == RunKind::horizon ? set.horizons : set.runs).push_back(std::move(r));
    }
    return set;
}

}  // namespace rotbench
