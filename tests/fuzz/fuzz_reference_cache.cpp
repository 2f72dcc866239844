// libFuzzer target: the reference cache's decoder (harness/store/reference_cache.hpp), which reads
// files from a shared cache directory that anything may have damaged. Every input must give a
// trajectory whose size matches its body count, or none; never a crash or a huge allocation.
#include "harness/store/reference_cache.hpp"
#include "tests/fuzz/fuzz_input.hpp"

using namespace rotbench;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto trajectory = decode_trajectory(fuzz::text(data, size), "key");
    if (trajectory && (trajectory->bodies == 0 || trajectory->values.size() % (trajectory->bodies * Trajectory::width) != 0))
        __builtin_trap();
    return 0;
}
