// libFuzzer target: the parsers of option values — number lists (--dt, --zeta), id lists
// (--scenes, --schemes), --shard K/N, and --set SCENE.KEY=VALUE followed by the plan of the
// sweep it sets up (the scene checks the value).
#include "harness/cli/config.hpp"
#include "harness/store/parse.hpp"
#include "harness/scenes/scene.hpp"
#include "harness/store/shard.hpp"
#include "schemes/scheme.hpp"
#include "tests/fuzz/fuzz_input.hpp"

using namespace rotbench;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string value = fuzz::text(data, size);
    fuzz::parse_or_input_error([&] { parse_positive_list(value, "--dt"); });
    fuzz::parse_or_input_error([&] { parse_nonnegative_list(value, "--zeta"); });
    fuzz::parse_or_input_error([&] { parse_id_list(value, SceneRegistry::instance(), "scene"); });
    fuzz::parse_or_input_error([&] { parse_id_list(value, SchemeRegistry::instance(), "scheme"); });
    fuzz::parse_or_input_error([&] { parse_shard(value); });
    fuzz::parse_or_input_error([&] {
        SweepSpec spec;
        add_setting(spec, value);
        for (const auto& [scene, settings] : spec.params) spec.scenes.push_back(scene);
        plan_sweep(spec);
    });
    return 0;
}
