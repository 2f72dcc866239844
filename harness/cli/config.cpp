#include "harness/cli/config.hpp"

#include "harness/store/parse.hpp"
#include "harness/store/toml_input.hpp"
#include "harness/scenes/scene.hpp"
#include "schemes/scheme.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {

namespace {

SweepSpec config_from_toml(const toml::table& root, const std::string& path) {
    SweepSpec spec;
    for (auto&& [name, node] : root) {
        const std::string table_name(name.str());
        const auto* table = node.as_table();
        if (!table) toml_error(path, node, "'" + table_name + "' must be a table ([run] or [SCENE])");
        if (table_name == "run") {
            for (auto&& [k, v] : *table) {
                const std::string key(k.str());
                if (key == "scenes") spec.scenes = ids(path, key, v, SceneRegistry::instance(), "scene");
                else if (key == "schemes") spec.schemes = ids(path, key, v, SchemeRegistry::instance(), "scheme");
                else if (key == "dt") {
                    spec.dts = numbers(path, key, v);
                    for (auto dt = spec.dts.begin(); dt != spec.dts.end(); ++dt) {
                        if (!(*dt > 0.0) || !std::isfinite(*dt)) toml_error(path, v, "'dt' values must be finite numbers greater than 0");
                        if (std::find(spec.dts.begin(), dt, *dt) != dt) toml_error(path, v, fmt::format("'dt': {} is given twice", *dt));
                    }
                } else if (key == "t_end") {
                    spec.t_end = positive_number(path, key, v);
                } else {
                    toml_error(path, v, "unknown key '" + key + "' in [run]; valid keys: scenes, schemes, dt, t_end");
                }
            }
            continue;
        }
        if (!SceneRegistry::instance().contains(table_name))
            toml_error(path, node, "unknown table [" + table_name + "]; valid tables: run, " + join(SceneRegistry::instance().ids(), ", "));
        auto& overrides = spec.params[table_name];
        for (auto& o : scene_overrides(path, table_name, *table)) overrides.push_back(std::move(o));
    }
    return spec;
}

}  // namespace

SweepSpec load_config(const std::string& path) { return config_from_toml(parse_toml_file(path), path); }

SweepSpec parse_config(std::string_view text, const std::string& name) { return config_from_toml(parse_toml_text(text, name), name); }

void add_setting(SweepSpec& spec, const std::string& text) {
    const auto dot = text.find('.'), eq = text.find('=');
    if (dot == std::string::npos || eq == std::string::npos || dot > eq || dot == 0 || eq == dot + 1)
        throw InputError("--set '" + text + "': expected SCENE.KEY=VALUE");
    const std::string scene = text.substr(0, dot), key = text.substr(dot + 1, eq - dot - 1);
    SceneRegistry::instance().at(scene, "scene");
    std::vector<double> values;
    for (const auto& part : split_commas(text.substr(eq + 1))) values.push_back(parse_finite(part, "--set " + scene + "." + key));
    spec.params[scene].push_back({key, values});
}

ParamOverrides scene_settings(const std::string& scene, const std::vector<std::string>& settings) {
    SweepSpec spec;
    for (const auto& s : settings) add_setting(spec, s.find('.') < s.find('=') ? s : scene + "." + s);
    ParamOverrides overrides;
    for (const auto& [scene_id, list] : spec.params) {
        if (scene_id != scene) throw InputError("--set names scene '" + scene_id + "', but the scene is '" + scene + "'");
        overrides = list;
    }
    return overrides;
}

}  // namespace rotbench
