// The limits a batch system sets never crash rotbench: it does the work with what it is given
// (harness/exec/parallel.hpp).
#include "harness/exec/parallel.hpp"

#include <catch2/catch.hpp>
#include <atomic>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace rotbench;

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
