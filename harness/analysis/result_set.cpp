#include "harness/analysis/result_set.hpp"

#include "harness/scenes/stability_probe.hpp"

namespace rotbench {

SchemeInfo scheme_info(const std::string& id) {
    const auto& e = SchemeRegistry::instance().at(id, "scheme");
    return {e.id, e.summary, e.source, e.notes, e.extra};
}

ResultSet describe(std::vector<RunResult> runs) {
    ResultSet set;
    for (const auto& r : runs) {
        if (!set.scenes.count(r.spec.scene)) {
            const auto& entry = SceneRegistry::instance().at(r.spec.scene, "scene");
            const auto scene = make_scene(r.spec.scene, r.spec.params);
            set.scenes[r.spec.scene] = {entry.id,
                                        entry.summary,
                                        entry.source,
                                        entry.notes,
                                        scene->reference_kind(),
                                        scene->conserves_energy(),
                                        scene->conserves_angular_momentum(),
                                        scene->torque_depends_on_orientation(),
                                        scene->initial_state().size()};
            auto& info = set.scenes[r.spec.scene];
            info.stability_scene = dynamic_cast<const StabilityProbe*>(scene.get()) != nullptr;
            for (const auto& p : scene->params.entries())
                if (p.key == "zeta" && p.value.size() == 1) info.zeta = p.value.front();
        }
        if (!set.schemes.count(r.spec.scheme) && SchemeRegistry::instance().contains(r.spec.scheme))
            set.schemes[r.spec.scheme] = scheme_info(r.spec.scheme);
    }
    set.runs = std::move(runs);
    return set;
}

}  // namespace rotbench
