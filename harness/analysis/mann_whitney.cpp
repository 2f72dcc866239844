#include "harness/analysis/mann_whitney.hpp"

#include <algorithm>
#include <cmath>
#include <gsl/gsl_cdf.h>
#include <utility>

namespace rotbench {

UTest mann_whitney(const std::vector<double>& a, const std::vector<double>& b) {
    UTest t;
    const double n1 = static_cast<double>(a.size()), n2 = static_cast<double>(b.size());
    if (a.size() < 5 || b.size() < 5) return t;
    // Ranks of the pooled sample, ties given their mean rank.
    std::vector<std::pair<double, int>> pooled;
    for (double x : a) pooled.push_back({x, 0});
    for (double x : b) pooled.push_back({x, 1});
    std::sort(pooled.begin(), pooled.end());
    double rank_sum_a = 0, tie_term = 0;
    for (std::size_t i = 0; i < pooled.size();) {
        std::size_t j = i;
        while (j < pooled.size() && pooled[j].first == pooled[i].first) ++j;
        const double rank = 0.5 * static_cast<double>(i + 1 + j);  // mean of ranks i+1 ... j
        const double ties = static_cast<double>(j - i);
        tie_term += ties * ties * ties - ties;
        for (std::size_t k = i; k < j; ++k)
            if (pooled[k].second == 0) rank_sum_a += rank;
        i = j;
    }
    t.u = rank_sum_a - n1 * (n1 + 1) / 2;
    const double n = n1 + n2, mean = n1 * n2 / 2;
    const double variance = n1 * n2 / 12 * ((n + 1) - tie_term / (n * (n - 1)));
    t.valid = true;
    if (variance <= 0) return t;  // every value the same: no evidence of a difference
    const double z = (std::abs(t.u - mean) - 0.5) / std::sqrt(variance);
    t.p = std::min(1.0, 2.0 * gsl_cdf_ugaussian_Q(std::max(z, 0.0)));
    return t;
}

}  // namespace rotbench
