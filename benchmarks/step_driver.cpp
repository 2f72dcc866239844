// Steps N bodies S times with one scheme and exits: the program that callgrind counts in
// benchmarks/instructions.sh. The count of a run with 2S steps minus that of a run with S
// steps is S steps' worth of instructions, free of start-up and set-up; divided by N S it
// is the scheme's instructions per body-step, a figure that does not depend on the load of
// a shared machine.
#include "benchmarks/random_bodies.hpp"
#include "schemes/scheme.hpp"

#include <cstdio>
#include <cstdlib>
#include <string>

using namespace rotbench;

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: rotbench_step_driver SCHEME BODIES STEPS\n");
        return 2;
    }
    try {
        const auto make = SchemeRegistry::instance().at(argv[1], "scheme").make;
        const auto n = static_cast<std::size_t>(std::stoul(argv[2]));
        const long steps = std::stol(argv[3]);
        Bodies b = random_bodies(n);
        auto scheme = make();
        scheme->start(b);
        for (long s = 0; s < steps; ++s) {
            scheme->predict(b, 1e-4);
            scheme->correct(b, 1e-4);
        }
        double checksum = 0;  // keeps the work observable
        for (std::size_t i = 0; i < n; ++i) checksum += b.omega[i].sum();
        std::printf("%.17g\n", checksum);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "rotbench_step_driver: %s\n", e.what());
        return 2;
    }
}
