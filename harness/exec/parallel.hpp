// Runs work(i) for i = 0 .. count-1 on `jobs` threads (the caller's among them). Each index
// runs once; an exception does not stop the other indices, and the first one is rethrown
// after all have finished, on the calling thread. When the system will not make as many
// threads (an address-space or process limit, as batch systems set), the work runs on those
// it made, the caller's at least, and a line on stderr says so.
#pragma once

#include "harness/exec/machine.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace rotbench {

template <class Work>
void parallel_for(std::size_t count, int jobs, Work&& work) {
    std::atomic<std::size_t> next{0};
    std::mutex error_mutex;
    std::exception_ptr error;
    auto worker = [&] {
        for (std::size_t i = next++; i < count; i = next++) {
            try {
                work(i);
            } catch (...) {
                std::lock_guard lock(error_mutex);
                if (!error) error = std::current_exception();
            }
        }
    };
    std::vector<std::thread> threads;
    const int wanted = std::max(1, std::min<int>(jobs, static_cast<int>(std::min<std::size_t>(count, 1u << 20))));
    const int affordable = static_cast<int>(std::clamp<long>(long{affordable_threads()} + 1, 1, wanted));  // the caller's too
    if (affordable < wanted)
        std::fprintf(stderr, "rotbench: the address-space limit leaves room for %d of %d threads; running on %d\n", affordable, wanted,
                     affordable);
    try {
        for (int j = 1; j < affordable; ++j) threads.emplace_back(worker);
    } catch (const std::system_error& e) {
        std::fprintf(stderr, "rotbench: could start %zu of %d threads (%s); running on %zu\n", threads.size() + 1, affordable, e.what(),
                     threads.size() + 1);
    }
    worker();
    for (auto& t : threads) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace rotbench
