// Steps N bodies S times with one scheme and exits: the program that callgrind counts in
// benchmarks/instructions.sh. The count of a run with 2S steps minus that of a run with S
// steps is S steps' worth of instructions, free of start-up and set-up; divided by N S it
// is the scheme's instructions per body-step, a figure that does not depend on the load of
// a shared machine.
#include "schemes/scheme.hpp"

#include <cstdio>
#include <cstdlib>
#include <random>
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
        Bodies b;
        b.resize(n);
        std::mt19937_64 rng(20261122);  // the state of benchmarks/batched_step.cpp
        std::uniform_real_distribution<double> u(-1.0, 1.0), moment(1.0, 3.0);
        for (std::size_t i = 0; i < n; ++i) {
            b.inertia.set(i, Vec3(moment(rng), moment(rng), moment(rng)));
            b.orientation.set(i, Quat(u(rng), u(rng), u(rng), u(rng)).normalized());
            b.omega.set(i, Vec3(u(rng), u(rng), u(rng)));
            b.torque.set(i, Vec3(u(rng), u(rng), u(rng)));
        }
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
