#include "harness/exec/interrupt.hpp"
#include "harness/exec/run_kinds.hpp"
#include "harness/exec/timing.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

namespace rotbench {

namespace {

// The distribution-free interval of a median from n samples: the k-th smallest and k-th
// largest, with k the largest for which P(Binomial(n, 1/2) < k) <= 2.5 % (covers >= 95 %).
std::pair<double, double> median_interval(std::vector<double> sorted) {
    std::sort(sorted.begin(), sorted.end());
    const int n = static_cast<int>(sorted.size());
    double below = std::pow(0.5, n), term = below;  // P(X <= j), P(X = j)
    int k = 0;
    for (int j = 0; below <= 0.025 && j < n / 2; ++j) {
        k = j + 1;
        term *= static_cast<double>(n - j) / (j + 1);
        below += term;
    }
    if (k == 0) return {sorted.front(), sorted.back()};  // too few pairs for any interval
    return {sorted[k - 1], sorted[n - k]};
}

}  // namespace

RunResult run_cost(const RunSpec& requested, const SchemeFactory& make) {
    const auto scene = scene_of(requested);
    RunResult result{requested, {}, {}};
    result.spec.t_end = scene->t_end();
    const double dt = requested.dt;
    const std::int64_t steps = std::min(step_count(result.spec.t_end, dt), timing_sample_steps);
    const SchemeFactory direct = registered_scheme("direct");
    const auto seconds = [&](const SchemeFactory& factory) {
        Bodies bodies = scene->initial_state();
        auto scheme = factory();
        std::int64_t evals = 0;
        const double start = thread_cpu_seconds();
        simulate(*scene, *scheme, bodies, dt, steps, evals, [](std::int64_t, double, const Bodies&) { return !interrupt_signal(); });
        return thread_cpu_seconds() - start;
    };
    std::vector<double> ratios, scheme_seconds;
    try {
        seconds(make), seconds(direct);  // warm both: the first pair would otherwise pay for the caches
        // ABBA: a drift in the machine's speed during one pair falls on both of its halves alike.
        for (int i = 0; i < cost_pairs && !interrupt_signal(); ++i) {
            double a = 0, b = 0;
            if (i % 2 == 0) a = seconds(make), b = seconds(direct);
            else b = seconds(direct), a = seconds(make);
            ratios.push_back(a / b);
            scheme_seconds.push_back(a);
        }
    } catch (...) {
        result.failure = caught_failure(requested.scheme);
        return result;
    }
    if (interrupt_signal()) {
        result.interrupted = true;
        return result;
    }
    std::vector<double> sorted = ratios;
    std::sort(sorted.begin(), sorted.end());
    const auto [lo, hi] = median_interval(ratios);
    std::sort(scheme_seconds.begin(), scheme_seconds.end());
    result.metrics = {{metric::cost_ratio, sorted[sorted.size() / 2]},
                      {metric::cost_ratio_lo, lo},
                      {metric::cost_ratio_hi, hi},
                      {metric::ns_per_step, scheme_seconds[scheme_seconds.size() / 2] / static_cast<double>(steps) * 1e9},
                      {metric::timing_repeats, static_cast<double>(ratios.size())},
                      {metric::timed_steps, static_cast<double>(steps)}};
    result.timing_samples = ratios;
    return result;
}

}  // namespace rotbench
