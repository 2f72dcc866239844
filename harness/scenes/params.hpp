// Scene parameters: named numbers and vectors with units, declared by each scene,
// overridden by `--set SCENE.KEY=VALUE` or a TOML config (docs/ids.md lists every key).
#pragma once

#include "schemes/registry.hpp"
#include "schemes/bodies.hpp"

#include <string>
#include <utility>
#include <vector>

namespace rotbench {

// Overrides for one scene, in the order given: key -> values (a scalar has one value).
using ParamOverrides = std::vector<std::pair<std::string, std::vector<double>>>;

class Params {
public:
    struct Entry {
        std::string key, unit, help;
        std::vector<double> value, default_value;
    };

    void set_owner(std::string scene_id) { scene_id_ = std::move(scene_id); }
    const std::string& owner() const { return scene_id_; }

    void declare(std::string key, std::vector<double> value, std::string unit, std::string help);

    // Throws InputError naming scene.key: unknown key (the valid ones listed), wrong
    // number of values, or a value that is not finite.
    void set(const std::string& key, const std::vector<double>& values);
    void apply(const ParamOverrides& overrides);

    double number(const std::string& key) const;
    Vec3 vec3(const std::string& key) const;
    Quat quat(const std::string& key) const;  // w, x, y, z; must be nonzero, returned normalised
    const std::vector<Entry>& entries() const { return entries_; }
    // Every key and value, for cache keys and provenance.
    std::string canonical() const;

    // For a scene's validation: throws InputError "scene.key: message" unless ok.
    void require(bool ok, const std::string& key, const std::string& message) const;
    // The checks most scenes need.
    double positive(const std::string& key) const;
    Vec3 positive_vec3(const std::string& key) const;
    // Principal moments: positive and, for a real body, each at most the sum of the other
    // two. `real_body = false` admits any positive moments (Euler's equations alone).
    Vec3 principal_moments(const std::string& key, bool real_body = true) const;

private:
    const Entry& find(const std::string& key) const;
    std::string scene_id_;
    std::vector<Entry> entries_;
};

}  // namespace rotbench
