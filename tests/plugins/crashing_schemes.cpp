// Test plug-in: schemes that crash, abort, exit, hang, exhaust memory, throw a non-standard
// exception or leave a process behind. Each takes down only its own run: the worker process
// it is isolated in.
#include "schemes/scheme.hpp"
#include <cerrno>  // program_invocation_short_name
#include <csignal>
#include <cstring>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>
#include <vector>
#include <thread>
namespace {
using namespace rotbench;
int* volatile null_target = nullptr;  // read at run time: the store below is a real SIGSEGV
template <int Mode> struct Bad {
    struct Memory {};
    static void start(const RigidBody&, Memory&) {}
    static void predict(RigidBody&, Memory&, double) {
        if constexpr (Mode == 0 || Mode == 8) *null_target = 1;
        if constexpr (Mode == 1) std::abort();
        if constexpr (Mode == 2) std::exit(7);
        if constexpr (Mode == 3) for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));
        if constexpr (Mode == 4) { std::vector<std::vector<char>> hog; for (;;) hog.emplace_back(1 << 26, 'x'); }
        if constexpr (Mode == 5) throw 42;
        if constexpr (Mode == 6) leave_a_process();
        // Steps in the step driver (callgrind's count) and crashes in the benchmark: the cost
        // table's case of a process that dies after timing the schemes before it.
        if constexpr (Mode == 7)
            if (std::strcmp(program_invocation_short_name, "rotbench_bench") == 0) *null_target = 1;
    }
    // Once per worker: a child that holds the worker's output pipes and never ends; its pid goes
    // to the file $ROTBENCH_TEST_ORPHAN, for the test to look for it afterwards.
    static void leave_a_process() {
        static bool done = false;
        if (done) return;
        done = true;
        if (const pid_t child = ::fork(); child == 0) {
            for (;;) ::pause();
        } else if (const char* file = std::getenv("ROTBENCH_TEST_ORPHAN")) {
            if (std::FILE* f = std::fopen(file, "w")) {
                std::fprintf(f, "%d\n", static_cast<int>(child));
                std::fclose(f);
            }
        }
    }
    static void correct(RigidBody&, Memory&, double) {}
};
const RegisterScheme<Bad<0>> a("bad_segfault", "segfaults", "t", "", {.sound = false});
const RegisterScheme<Bad<1>> b("bad_abort", "aborts", "t", "", {.sound = false});
const RegisterScheme<Bad<2>> c("bad_exit", "exits", "t", "", {.sound = false});
const RegisterScheme<Bad<3>> d("bad_hang", "hangs", "t", "", {.sound = false});
const RegisterScheme<Bad<4>> e("bad_oom", "eats memory", "t", "", {.sound = false});
const RegisterScheme<Bad<5>> f("bad_throw42", "throws 42", "t", "", {.sound = false});
const RegisterScheme<Bad<6>> g("bad_orphan", "leaves a process holding its output", "t", "", {.sound = false});
const RegisterScheme<Bad<7>> h("bad_in_benchmark", "segfaults in rotbench_bench only", "t", "", {.sound = false});
// A candidate its author believes sound: `advise` considers it (it skips the controls above).
const RegisterScheme<Bad<8>> i("bad_sound_segfault", "segfaults, though it claims to be sound", "t", "", {.sound = true});
}
