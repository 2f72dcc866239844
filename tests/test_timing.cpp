// How runs are timed and what they share: the timing sample and the shared references.
#include "harness/exec/run.hpp"
#include "harness/exec/shared_trajectory.hpp"

#include <atomic>
#include <catch2/catch.hpp>
#include <cmath>
#include <new>
#include <stdexcept>
#include <thread>

using namespace rotbench;

TEST_CASE("a run of more than timing_sample_steps is timed on 32 equal stretches of them, a shorter one whole") {
    static_assert(timing_sample_steps == 10000);  // README "The run's own timing" says 1e4
    const RunResult long_run = run_one({"asymmetric_free", "direct", 1e-3, 30.0});  // 30 000 steps
    CHECK(long_run.value("steps") == 30000);
    CHECK(long_run.value("timed_steps") == 32 * 312);
    const RunResult short_run = run_one({"asymmetric_free", "direct", 1e-2, 0.0});
    CHECK(short_run.value("timed_steps") == short_run.value("steps"));
    for (const RunResult* r : {&long_run, &short_run}) {
        CHECK(r->value("timing_repeats") >= 3);
        CHECK(r->value("cpu_seconds") > 0.0);
        CHECK(r->value("cpu_seconds_min") <= r->value("cpu_seconds"));
        CHECK(r->value("cpu_seconds") <= r->value("cpu_seconds_max"));
        // Scaled to the whole run: ns_per_step is cpu_seconds over all the steps, not the timed ones.
        CHECK(r->value("ns_per_step") == Approx(r->value("cpu_seconds") / r->value("steps") * 1e9).epsilon(1e-12));
    }
}

TEST_CASE("a reference trajectory is computed once per key, even when runs ask for it at the same time") {
    std::atomic<int> computed = 0;
    const auto compute = [&] {
        ++computed;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));  // long enough for the other thread to ask meanwhile
        Trajectory t;
        t.bodies = 1;
        t.values.assign(Trajectory::width, 1.0);
        return t;
    };
    std::shared_ptr<const Trajectory> a, b;
    std::thread other([&] { a = shared_trajectory("test|shared-once", compute); });
    b = shared_trajectory("test|shared-once", compute);
    other.join();
    CHECK(computed == 1);
    CHECK(a == b);
    CHECK(shared_trajectory("test|shared-other", compute) != a);
    CHECK(computed == 2);
}

TEST_CASE("a reference that fails by its scene is kept failed, and one that ran out of memory is tried again") {
    int attempts = 0;
    const auto failing = [&]() -> Trajectory {
        ++attempts;
        throw std::runtime_error("more than 100 steps");
    };
    // The same key fails the same way: every other scheme's run gets the error at once.
    CHECK_THROWS_WITH(shared_trajectory("test|fails", failing), "more than 100 steps");
    CHECK_THROWS_WITH(shared_trajectory("test|fails", failing), "more than 100 steps");
    CHECK(attempts == 1);
    int tries = 0;
    const auto out_of_memory = [&]() -> Trajectory {
        ++tries;
        throw std::bad_alloc();
    };
    CHECK_THROWS_AS(shared_trajectory("test|memory", out_of_memory), std::bad_alloc);
    CHECK_THROWS_AS(shared_trajectory("test|memory", out_of_memory), std::bad_alloc);
    CHECK(tries == 2);
}
