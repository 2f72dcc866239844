#include "harness/config.hpp"

#include "harness/parse.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

namespace rotbench {
namespace {

std::string where(const std::string& path, const toml::source_region& src) {
    return fmt::format("{}:{}:{}", path, src.begin.line, src.begin.column);
}

[[noreturn]] void fail(const std::string& path, const toml::node& node, const std::string& message) {
    throw InputError(where(path, node.source()) + ": " + message);
}

std::vector<double> numbers(const std::string& path, const std::string& key, const toml::node& node) {
    std::vector<double> out;
    auto one = [&](const toml::node& n) {
        const auto v = n.value<double>();  // integers convert; strings, booleans do not
        if (!v || n.is_boolean()) fail(path, n, "'" + key + "' must be a number or an array of numbers");
        out.push_back(*v);
    };
    if (const auto* array = node.as_array()) {
        if (array->empty()) fail(path, node, "'" + key + "' is an empty array");
        for (const auto& item : *array) one(item);
    } else {
        one(node);
    }
    return out;
}

std::vector<std::string> strings(const std::string& path, const std::string& key, const toml::node& node) {
    const auto* array = node.as_array();
    if (!array) fail(path, node, "'" + key + "' must be an array of strings");
    std::vector<std::string> out;
    for (const auto& item : *array) {
        const auto s = item.value<std::string>();
        if (!s || !item.is_string()) fail(path, item, "'" + key + "' must be an array of strings");
        out.push_back(*s);
    }
    return out;
}

template <class Product>
std::vector<std::string> ids(const std::string& path, const std::string& key, const toml::node& node,
                             const Registry<Product>& registry, const std::string& kind) {
    try {
        return parse_id_list(join(strings(path, key, node), ","), registry, kind);
    } catch (const InputError& e) {
        if (std::string(e.what()).rfind(path, 0) == 0) throw;
        fail(path, node, e.what());
    }
}

}  // namespace

SweepSpec load_config(const std::string& path) {
    toml::table root;
    try {
        root = toml::parse_file(path);
    } catch (const toml::parse_error& e) {
        const std::string description(e.description());
        if (e.source().begin.line == 0) throw InputError(path + ": cannot read the file (" + description + ")");
        throw InputError(where(path, e.source()) + ": " + description);
    }
    SweepSpec spec;
    for (auto&& [name, node] : root) {
        const std::string table_name(name.str());
        const auto* table = node.as_table();
        if (!table) fail(path, node, "'" + table_name + "' must be a table ([run] or [SCENE])");
        if (table_name == "run") {
            for (auto&& [k, v] : *table) {
                const std::string key(k.str());
                if (key == "scenes") spec.scenes = ids(path, key, v, SceneRegistry::instance(), "scene");
                else if (key == "schemes") spec.schemes = ids(path, key, v, SchemeRegistry::instance(), "scheme");
                else if (key == "dt") {
                    spec.dts = numbers(path, key, v);
                    for (double dt : spec.dts)
                        if (!(dt > 0.0) || !std::isfinite(dt)) fail(path, v, "'dt' values must be finite numbers greater than 0");
                } else if (key == "t_end") {
                    const auto t = numbers(path, key, v);
                    if (t.size() != 1 || !(t[0] > 0.0) || !std::isfinite(t[0]))
                        fail(path, v, "'t_end' must be one finite number greater than 0");
                    spec.t_end = t[0];
                } else {
                    fail(path, v, "unknown key '" + key + "' in [run]; valid keys: scenes, schemes, dt, t_end");
                }
            }
            continue;
        }
        if (!SceneRegistry::instance().contains(table_name))
            fail(path, node, "unknown table [" + table_name + "]; valid tables: run, " + join(SceneRegistry::instance().ids(), ", "));
        auto& overrides = spec.params[table_name];
        const auto probe = SceneRegistry::instance().at(table_name, "scene").make();
        for (auto&& [k, v] : *table) {
            const std::string key(k.str());
            const auto values = numbers(path, key, v);
            try {
                probe->params.set(key, values);  // names the key and the valid ones
            } catch (const InputError& e) {
                fail(path, v, e.what());
            }
            overrides.push_back({key, values});
        }
    }
    return spec;
}

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

}  // namespace rotbench
