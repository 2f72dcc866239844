// Steps N bodies S times with one scheme, for each (N, S) pair given, and exits: the program
// that callgrind counts for the cost table (benchmarks/cost.py). Run under
//   valgrind --tool=callgrind --collect-atstart=no
// only the S measured steps of each pair are counted (collection is switched on around
// them, after two unmeasured steps that bind symbols and touch the memory), and each pair's
// count is dumped to a file of its own. Divided by N S it is the scheme's instructions per
// body-step, a figure that does not depend on the load of a shared machine. Without
// valgrind the requests do nothing.
//   rotbench_step_driver [--plugin PATH]... SCHEME N S [N S]...
//   rotbench_step_driver [--plugin PATH]... --list      the scheme ids, one per line
#include "benchmarks/plugin_args.hpp"
#include "benchmarks/random_bodies.hpp"
#include "schemes/scheme.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>
#include <valgrind/callgrind.h>

using namespace rotbench;

namespace {

long positive(const char* text) {
    char* end = nullptr;
    const long v = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || v <= 0) throw std::invalid_argument(std::string("not a positive integer: ") + text);
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    load_plugin_args(argc, argv, "rotbench_step_driver");
    if (argc == 2 && std::string(argv[1]) == "--list") {
        for (const auto& id : SchemeRegistry::instance().ids()) std::printf("%s\n", id.c_str());
        return 0;
    }
    if (argc < 4 || argc % 2 != 0) {
        std::fprintf(stderr, "usage: rotbench_step_driver [--plugin PATH]... SCHEME N S [N S]...\n");
        return 2;
    }
    try {
        const auto make = SchemeRegistry::instance().at(argv[1], "scheme").make;
        double checksum = 0;  // keeps the work observable
        for (int a = 2; a < argc; a += 2) {
            const auto n = static_cast<std::size_t>(positive(argv[a]));
            const long steps = positive(argv[a + 1]);
            Bodies b = random_bodies(n);
            auto scheme = make();
            scheme->start(b);
            for (long s = 0; s < steps + 2; ++s) {
                if (s == 2) CALLGRIND_TOGGLE_COLLECT;
                scheme->predict(b, 1e-4);
                scheme->correct(b, 1e-4);
            }
            CALLGRIND_TOGGLE_COLLECT;
            CALLGRIND_DUMP_STATS;
            for (std::size_t i = 0; i < n; ++i) checksum += b.omega[i].sum();
        }
        std::printf("%.17g\n", checksum);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rotbench_step_driver: %s\n", e.what());
        return 2;
    }
}
