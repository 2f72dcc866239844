// libFuzzer target: the gate file parser (harness/gate.cpp), as `rotbench gate FILE`
// before anything runs.
#include "harness/gate/gate_file.hpp"
#include "tests/fuzz/fuzz_input.hpp"

using namespace rotbench;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::parse_or_input_error([&] { parse_gate(fuzz::text(data, size), "fuzz.toml"); });
    return 0;
}
