// A set of run results together with what the report needs to know about their schemes and
// scenes, so that reports only consume it: they build no scene and read no registry.
#pragma once

#include "harness/exec/run.hpp"
#include "harness/scenes/scene.hpp"
#include "harness/store/scheme_record.hpp"
#include "schemes/scheme.hpp"

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace rotbench {

struct SceneInfo {
    std::string id, summary, source, notes;
    Scene::ReferenceKind reference = Scene::ReferenceKind::none;
    bool conserves_energy = false, conserves_angular_momentum = false, torque_depends_on_orientation = false;
    std::size_t bodies = 0;
    bool stability_scene = false;  // one of the stability study's (a StabilityProbe)
    double zeta = 0;               // its damping ratio, for a contact scene
};


struct ResultSet {
    std::vector<RunResult> runs;      // every run but the horizon runs
    std::vector<RunResult> horizons;  // the horizon runs (RunKind::horizon), for the bounded-energy verdicts
    std::vector<RunResult> declined;  // runs a client's program declined (metric::declined): in no table
    std::map<std::string, SceneInfo> scenes;    // every scene of the runs (with the parameters of its first run)
    SchemeInfos schemes;  // every scheme of the runs registered in this process or recorded with them

    const SceneInfo& scene(const std::string& id) const { return scenes.at(id); }
    const SchemeInfo* scheme(const std::string& id) const {
        const auto it = schemes.find(id);
        return it == schemes.end() ? nullptr : &it->second;
    }
};

// The runs with the descriptions of their scenes and schemes (InputError for an unknown scene);
// a scheme not registered in this process is described as `recorded` says (schemes.json).
ResultSet describe(std::vector<RunResult> runs, const SchemeInfos& recorded = {});
SceneInfo scene_info(const Scene& scene);

}  // namespace rotbench
