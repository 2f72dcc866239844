// The limits a batch system sets never crash rotbench: it does the work with what it is given
// (harness/exec/parallel.hpp), and its own limits are never blamed on a scheme.
#include "harness/exec/isolation.hpp"
#include "harness/exec/parallel.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/skip.hpp"

#include <catch2/catch.hpp>
#include <atomic>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace rotbench;
using namespace rotbench::test;

TEST_CASE("limits: threads the system will not make cost parallelism, never the work") {
    // In a child whose address space leaves room for a few thread stacks only (8 MiB each).
    const pid_t pid = fork();
    if (pid == 0) {
        std::vector<char> warm(1 << 20);  // the child's heap is in use before the limit
        rlimit limit{};
        getrlimit(RLIMIT_AS, &limit);
        std::FILE* maps = std::fopen("/proc/self/statm", "r");
        unsigned long pages = 0;
        if (!maps || std::fscanf(maps, "%lu", &pages) != 1) _exit(3);
        std::fclose(maps);
        limit.rlim_cur = pages * static_cast<unsigned long>(sysconf(_SC_PAGESIZE)) + (64ul << 20);
        if (setrlimit(RLIMIT_AS, &limit) != 0) _exit(3);
        std::vector<std::atomic<int>> done(1000);
        parallel_for(done.size(), 256, [&](std::size_t i) { ++done[i]; });
        for (const auto& d : done)
            if (d != 1) _exit(1);
        _exit(warm.empty() ? 1 : 0);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    REQUIRE(WIFEXITED(status));  // not killed by std::terminate
    CHECK(WEXITSTATUS(status) == 0);
}

TEST_CASE("limits: rotbench's own out-of-memory is never the scheme's blow-up, and leaves no cut file") {
    if (!memory_limit_enforced()) ROTBENCH_SKIP("no memory limit holds here (AddressSanitizer's shadow memory takes it all)");
    const fs::path dir = fresh_dir("limits_memory");
    fs::create_directories(dir);
    // A million states of a million-step run, in 150 MB of address space: the records cannot fit.
    const Cli starved = binary({"trajectory", "--scene", "asymmetric_free", "--scheme", "direct", "--dt", "1e-6", "--samples", "1000000",
                                "--out", (dir / "t.csv").string()},
                               {}, [] {
                                   const rlimit limit{150ul << 20, 150ul << 20};
                                   setrlimit(RLIMIT_AS, &limit);
                               });
    CHECK(starved.status != 0);
    CHECK(starved.status != 4);  // not called a bug of rotbench's
    CHECK(one_line(starved.err));
    CHECK_THAT(starved.err, Catch::Contains("out of memory"));
    CHECK_THAT(starved.err, !Catch::Contains("blew up"));
    CHECK_FALSE(fs::exists(dir / "t.csv"));
    // A blow-up is the scheme's: its trajectory up to there is written, and said to be cut.
    const Cli blown = cli({"trajectory", "--scene", "sphere_pair", "--scheme", "direct", "--dt", "1e-3", "--out", (dir / "b.csv").string()});
    CHECK(blown.status == 0);
    CHECK_THAT(blown.err, Catch::Contains("direct blew up at step 21"));
    CHECK_THAT(blown.err, Catch::Contains("holds the trajectory up to there"));
    CHECK(fs::exists(dir / "b.csv"));
    fs::remove_all(dir);
}
