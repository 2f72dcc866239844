#include "harness/store/toml_input.hpp"

#include "harness/scenes/scene.hpp"
#include "harness/store/toml_ascii.hpp"
#include "harness/store/output_files.hpp"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>

namespace rotbench {


namespace {

std::string where(const std::string& path, const toml::source_region& src) {
    return fmt::format("{}:{}:{}", path, src.begin.line, src.begin.column);
}

}  // namespace

[[noreturn]] void toml_error(const std::string& path, const toml::node& node, const std::string& message) {
    throw InputError(where(path, node.source()) + ": " + message);
}

std::vector<double> numbers(const std::string& path, const std::string& key, const toml::node& node) {
    std::vector<double> out;
    auto one = [&](const toml::node& n) {
        const auto v = n.value<double>();  // integers convert; strings, booleans do not
        if (!v || n.is_boolean()) toml_error(path, n, "'" + key + "' must be a number or an array of numbers");
        out.push_back(*v);
    };
    if (const auto* array = node.as_array()) {
        if (array->empty()) toml_error(path, node, "'" + key + "' is an empty array");
        for (const auto& item : *array) one(item);
    } else {
        one(node);
    }
    return out;
}

std::vector<std::string> strings(const std::string& path, const std::string& key, const toml::node& node) {
    const auto* array = node.as_array();
    if (!array) toml_error(path, node, "'" + key + "' must be an array of strings");
    std::vector<std::string> out;
    for (const auto& item : *array) {
        const auto s = item.value<std::string>();
        if (!s || !item.is_string()) toml_error(path, item, "'" + key + "' must be an array of strings");
        out.push_back(*s);
    }
    return out;
}

double positive_number(const std::string& path, const std::string& key, const toml::node& node) {
    const auto v = numbers(path, key, node);
    if (v.size() != 1 || !(v[0] > 0.0) || !std::isfinite(v[0]))
        toml_error(path, node, "'" + key + "' must be one finite number greater than 0");
    return v[0];
}

std::string text(const std::string& path, const std::string& key, const toml::node& node) {
    const auto s = node.value<std::string>();
    if (!s || !node.is_string()) toml_error(path, node, "'" + key + "' must be a string");
    return *s;
}

toml::table parse_toml_file(const std::string& path) {
    // A configuration or gate file: a few kilobytes. 1 MiB bounds what a typo can make it read.
    return parse_toml_text(read_input_file(path, "", 1u << 20), path);
}

toml::table parse_toml_text(std::string_view text, const std::string& name) {
    const std::string ascii = ascii_toml(text, name);  // what toml++ 3.3.0 reads safely
    try {
        return toml::parse(ascii, name);
    } catch (const toml::parse_error& e) {
        throw InputError(where(name, e.source()) + ": " + std::string(e.description()));
    }
}

ParamOverrides scene_overrides(const std::string& path, const std::string& scene, const toml::table& table) {
    ParamOverrides overrides;
    const auto probe = SceneRegistry::instance().at(scene, "scene").make();
    for (auto&& [k, v] : table) {
        const std::string key(k.str());
        const auto values = numbers(path, key, v);
        try {
            probe->params.set(key, values);  // names the key and the valid ones
        } catch (const InputError& e) {
            toml_error(path, v, e.what());
        }
        overrides.push_back({key, values});
    }
    return overrides;
}

}  // namespace rotbench
