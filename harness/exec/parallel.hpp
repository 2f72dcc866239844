// Runs work(i) for i = 0 .. count-1 on `jobs` threads (the caller's among them). Each index
// runs once; an exception does not stop the other indices, and the first one is rethrown
// after all have finished, on the calling thread.
#pragma once

#include "harness/exec/machine.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
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
    for (int j = 1; j < std::max(1, jobs); ++j) threads.emplace_back(worker);
    worker();
    for (auto& t : threads) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace rotbench
