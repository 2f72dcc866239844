// Batched step benchmark (Google Benchmark): every registered scheme advances the rotation
// of N bodies (N = 1, 1e3, 1e6) through predict and correct, with the torques read from
// memory as a DEM code reads the ones its contact loop left there. Reported per body-step,
// beside, in the same run:
//   load_store   the same loops over the same state with a kernel that does nothing: the
//                cost of reading and writing the state, which no scheme can go below;
//   one_at_a_time/<scheme>  the same scheme driven body by body through the virtual
//                interface on a one-body state (copy in, predict, correct, copy out): the
//                straightforward way, against which the batched loops are measured.
// The schemes are the registered ones, and those of the plug-ins given with `--plugin PATH`:
// the same code that the scenes run. Sizes: 1, 1e3, 1e5 and 1e6 bodies (the cost table times
// a scheme of many thousand instructions per body-step, for which the memory traffic is a
// negligible part, at 1e5).
#include "benchmarks/plugin_args.hpp"
#include "benchmarks/random_bodies.hpp"
#include "schemes/scheme.hpp"

#include <benchmark/benchmark.h>
#include <malloc.h>
#include <map>

using namespace rotbench;

namespace {

constexpr double dt = 1e-4;

// Loads and stores every body's state and computes nothing. DoNotOptimize keeps the
// compiler from proving the stores redundant (they write back what was read).
struct LoadStoreOnly {
    struct Memory {};
    static void start(const RigidBody&, Memory&) {}
    static void predict(RigidBody& b, Memory&, double) { benchmark::DoNotOptimize(b); }
    static void correct(RigidBody& b, Memory&, double) { benchmark::DoNotOptimize(b); }
};

void per_body_step(benchmark::State& state, std::size_t n) {
    state.counters["ns_per_body_step"] =
        benchmark::Counter(static_cast<double>(n) * 1e-9, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// The random state of n bodies, drawn once per size and stepped in place by every benchmark:
// drawing a million bodies, or copying them (180 MB), took longer than a batched step of
// most schemes, at every repetition of every benchmark. A few hundred steps of 1e-4 s leave
// the states as random as they were.
Bodies& random_state(std::size_t n) {
    static std::map<std::size_t, Bodies> drawn;
    auto it = drawn.find(n);
    if (it == drawn.end()) it = drawn.emplace(n, random_bodies(n)).first;
    return it->second;
}

void batched(benchmark::State& state, std::function<std::unique_ptr<RotationScheme>()> make) {
    const auto n = static_cast<std::size_t>(state.range(0));
    Bodies& b = random_state(n);
    auto scheme = make();
    scheme->start(b);
    for (auto _ : state) {
        scheme->predict(b, dt);
        scheme->correct(b, dt);
        benchmark::DoNotOptimize(b.omega.x.data());
        benchmark::ClobberMemory();
    }
    per_body_step(state, n);
}

void one_at_a_time(benchmark::State& state, std::function<std::unique_ptr<RotationScheme>()> make) {
    const auto n = static_cast<std::size_t>(state.range(0));
    Bodies& b = random_state(n);
    Bodies one = random_bodies(1);
    auto scheme = make();
    scheme->start(one);
    for (auto _ : state) {
        for (std::size_t i = 0; i < n; ++i) {
            one.inertia.set(0, b.inertia[i]);
            one.orientation.set(0, b.orientation[i]);
            one.omega.set(0, b.omega[i]);
            one.torque.set(0, b.torque[i]);
            scheme->predict(one, dt);
            scheme->correct(one, dt);
            b.orientation.set(i, one.orientation[0]);
            b.omega.set(i, one.omega[0]);
        }
        benchmark::ClobberMemory();
    }
    per_body_step(state, n);
}

// Registration over whatever the registry holds once the plug-ins are loaded.
void register_benchmarks() {
    const auto sizes = [](benchmark::internal::Benchmark* bm) {
        bm->Arg(1)->Arg(1000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMicrosecond);
    };
    sizes(benchmark::RegisterBenchmark("load_store", batched, [] { return std::make_unique<BatchedScheme<LoadStoreOnly>>(); }));
    for (const auto& id : SchemeRegistry::instance().ids()) {
        const auto make = SchemeRegistry::instance().at(id, "scheme").make;
        sizes(benchmark::RegisterBenchmark(("batched/" + id).c_str(), batched, make));
        sizes(benchmark::RegisterBenchmark(("one_at_a_time/" + id).c_str(), one_at_a_time, make));
    }
}

}  // namespace

// The state's arrays (8 MB each at N = 1e6) come from the heap, not each from a mapping of its
// own. glibc maps a large block at the same offset in its page every time; whether it mapped
// or reused the heap varied between repetitions, and the batched times were bimodal (with
// every array at the same page offset the 20-odd arrays of a step most likely compete for
// the same cache sets; docs/performance.md). From the heap they lie at staggered offsets.
int main(int argc, char** argv) {
    mallopt(M_MMAP_THRESHOLD, 1 << 30);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    load_plugin_args(argc, argv, "rotbench_bench");
    register_benchmarks();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
}
