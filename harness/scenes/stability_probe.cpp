#include "harness/scenes/stability_probe.hpp"

#include "harness/scenes/scene.hpp"

namespace rotbench {

std::vector<std::string> stability_scene_ids() {
    std::vector<std::string> ids;
    for (const auto& id : SceneRegistry::instance().ids())
        if (SceneRegistry::instance().at(id, "scene").extra.stability) ids.push_back(id);
    return ids;
}

}  // namespace rotbench
