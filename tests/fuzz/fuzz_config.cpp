// libFuzzer target: the TOML run configuration (harness/config.cpp), then the sweep it
// describes planned (scene parameters checked by the scenes), as `rotbench run --config`.
#include "harness/cli/config.hpp"
#include "tests/fuzz/fuzz_input.hpp"

using namespace rotbench;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::parse_or_input_error([&] { plan_sweep(parse_config(fuzz::text(data, size), "fuzz.toml")); });
    return 0;
}
