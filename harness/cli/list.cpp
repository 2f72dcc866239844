// `rotbench list`: the registered schemes and scenes; `--params SCENE`: a scene's keys.
#include "harness/cli/verb.hpp"
#include "harness/scenes/scene.hpp"
#include "schemes/scheme.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace rotbench {
namespace {

// The width of the id column: the longest id, so that long plug-in ids keep the columns aligned.
template <class R>
std::size_t id_width(const R& registry, std::size_t at_least) {
    std::size_t width = at_least;
    for (const auto& id : registry.ids()) width = std::max(width, id.size());
    return width;
}

void list_params(const std::string& scene_id, std::ostream& out) {
    const auto scene = SceneRegistry::instance().at(scene_id, "scene").make();
    out << fmt::format("parameters of {} (--set {}.KEY=VALUE, or [{}] in a config):\n", scene_id, scene_id, scene_id);
    std::size_t key = 12, value_width = 24, unit = 10;
    std::vector<std::string> values;
    for (const auto& e : scene->params.entries()) {
        std::string value;
        for (double v : e.value) value += fmt::format("{}{}", value.empty() ? "" : ",", v);
        values.push_back(value);
        key = std::max(key, e.key.size());
        value_width = std::max(value_width, value.size());
        unit = std::max(unit, e.unit.size());
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto& e = scene->params.entries()[i];
        out << fmt::format("  {:<{}} {:<{}} {:<{}} {}\n", e.key, key, values[i], value_width, e.unit, unit, e.help);
    }
}

void list(std::ostream& out) {
    const auto& schemes = SchemeRegistry::instance();
    const auto& scenes = SceneRegistry::instance();
    const std::size_t width = std::max(id_width(schemes, 16), id_width(scenes, 16));
    out << "(rotbench list --params SCENE lists a scene's parameters)\n";
    out << "schemes:\n";
    for (const auto& id : schemes.ids()) {
        const auto& e = schemes.at(id, "scheme");
        out << fmt::format("  {:<{}} {}\n  {:<{}} ({})\n", id, width, e.summary, "", width, e.source);
    }
    out << "scenes:\n";
    for (const auto& id : scenes.ids()) {
        const auto& e = scenes.at(id, "scene");
        const auto scene = make_scene(id);
        std::string dts;
        for (double dt : scene->default_dts()) dts += fmt::format("{}{:g}", dts.empty() ? "" : ",", dt);
        out << fmt::format("  {:<{}} {}\n  {:<{}} (t_end {:g} s, dt {})\n", id, width, e.summary, "", width, scene->t_end(), dts);
    }
}

class ListVerb final : public Verb {
public:
    void add_options(CLI::App& command) override {
        command.add_option("--params", params_of_, "list the parameters of this scene");
    }
    int run(const Invocation& how) override {
        if (params_of_.empty()) list(how.out);
        else list_params(params_of_, how.out);
        return 0;
    }

private:
    std::string params_of_;
};

const RegisterVerb<ListVerb> registration("list", "list the registered schemes and scenes");

}  // namespace
}  // namespace rotbench
