// A set of run results together with what the report needs to know about their schemes and
// scenes, so that reports only consume it: they build no scene and read no registry.
#pragma once

#include "harness/exec/run.hpp"
#include "harness/scenes/scene.hpp"
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

struct SchemeInfo {
    std::string id, summary, source, notes;
    SchemeClaims claims;
    bool client = false;      // run by a program outside rotbench (harness/store/client.hpp)
    std::string counterpart;  // a client's: the built-in scheme it should equal (empty: none)
    std::string counterpart_note;  // why it is not that scheme's map, where it is not
};

struct ResultSet {
    std::vector<RunResult> runs;      // every run but the horizon runs
    std::vector<RunResult> horizons;  // the horizon runs (RunKind::horizon), for the bounded-energy verdicts
    std::map<std::string, SceneInfo> scenes;    // every scene of the runs (with the parameters of its first run)
    std::map<std::string, SchemeInfo> schemes;  // every scheme of the runs that is registered in this process

    const SceneInfo& scene(const std::string& id) const { return scenes.at(id); }
    const SchemeInfo* scheme(const std::string& id) const {
        const auto it = schemes.find(id);
        return it == schemes.end() ? nullptr : &it->second;
    }
};

// The runs with the descriptions of their scenes and schemes (InputError for an unknown scene).
ResultSet describe(std::vector<RunResult> runs);
SceneInfo scene_info(const Scene& scene);
SchemeInfo scheme_info(const std::string& id);  // of a registered scheme

}  // namespace rotbench
