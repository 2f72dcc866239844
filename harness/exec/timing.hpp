// CPU time of the calling thread, so that parallel runs do not inflate each other.
#pragma once

#include <algorithm>
#include <ctime>
#include <vector>

namespace rotbench {

inline double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

struct CpuTiming {
    double median = 0, min = 0, max = 0;
    int repeats = 0;
    std::vector<double> samples;  // every repeat, in the order measured
};

// Median CPU time of `work`; repeats at least `min_repeats` times and until `min_total`
// seconds were measured (at most 31 repeats). No call is discarded as a warm-up: the caller
// times a run right after its metrics run, which has already stepped the same scheme on the
// same scene (caches, branch predictors and pages are warm); a warm-up call and a longer
// floor did not change ns_per_step beyond the run-to-run noise (docs/performance.md). A call that takes longer than `long_call` seconds is measured once: its start-up costs are
// amortised, and repeating it would only spend time.
template <class Work>
CpuTiming median_cpu_seconds(Work&& work, int min_repeats = 3, double min_total = 0.003, double long_call = 0.5) {
    std::vector<double> samples;
    double total = 0.0;
    while (samples.size() < 31 && (samples.size() < static_cast<std::size_t>(min_repeats) || total < min_total)) {
        const double start = thread_cpu_seconds();
        work();
        samples.push_back(thread_cpu_seconds() - start);
        total += samples.back();
        if (samples.size() == 1 && samples.front() > long_call) break;
    }
    std::vector<double> sorted = samples;
    std::sort(sorted.begin(), sorted.end());
    return {sorted[sorted.size() / 2], sorted.front(), sorted.back(), static_cast<int>(sorted.size()), samples};
}

}  // namespace rotbench
