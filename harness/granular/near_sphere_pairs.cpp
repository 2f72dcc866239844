#include "harness/granular/near_sphere_pairs.hpp"

#include <algorithm>
#include <stdexcept>

namespace rotbench {

// A pair is listed, and the list kept, with this relative margin, far above round-off: the
// triangle inequality that keeps every contact then holds for the computed distances too.
constexpr double listing_margin = 1.0 + 1e-9;

bool NearSpherePairs::stale(const std::vector<Vec3>& centres) const {
    if (centres.size() != built_at_.size()) return true;
    const double moved = 0.25 * skin_ * skin_;  // half the skin, squared
    for (std::size_t s = 0; s < centres.size(); ++s)
        if (!((centres[s] - built_at_[s]).squaredNorm() * listing_margin <= moved)) return true;  // NaN too
    return false;
}

void NearSpherePairs::build(const std::vector<Vec3>& centres, const std::vector<double>& radii, const std::vector<Vec3>& stones,
                            const std::vector<std::size_t>& first_sphere, const std::vector<double>& reach, double skin) {
    if (!(skin > 0.0)) throw std::invalid_argument("NearSpherePairs: the skin must be positive");
    skin_ = skin;
    built_at_ = centres;
    auto end_of = [&](std::size_t s) { return s + 1 < first_sphere.size() ? first_sphere[s + 1] : centres.size(); };

    std::vector<std::pair<std::size_t, std::size_t>> stone_pairs;  // (lower, higher)
    const double largest = stones.empty() ? 0.0 : *std::max_element(reach.begin(), reach.end());
    cells_.build(stones, 2.0 * largest + skin);
    cells_.for_each_pair([&](std::size_t p, std::size_t q) {
        const double near = reach[p] + reach[q] + skin;
        if ((stones[p] - stones[q]).squaredNorm() < near * near * listing_margin) stone_pairs.emplace_back(std::min(p, q), std::max(p, q));
    });
    std::sort(stone_pairs.begin(), stone_pairs.end());

    first_neighbour_.assign(stones.size() + 1, 0);
    neighbours_.clear();
    low_first_.clear();
    high_first_.clear();
    auto close = [&](std::size_t i, std::size_t j) {
        const double near = radii[i] + radii[j] + skin;
        return (centres[i] - centres[j]).squaredNorm() < near * near * listing_margin;
    };
    std::size_t next = 0;
    for (std::size_t low = 0; low < stones.size(); ++low) {
        first_neighbour_[low] = neighbours_.size();
        for (; next < stone_pairs.size() && stone_pairs[next].first == low; ++next) {
            const std::size_t high = stone_pairs[next].second, begin = low_first_.size();
            for (std::size_t i = first_sphere[low]; i < end_of(low); ++i)
                for (std::size_t j = first_sphere[high]; j < end_of(high); ++j)
                    if (close(i, j)) low_first_.emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
            if (low_first_.size() == begin) continue;
            for (std::size_t k = begin; k < low_first_.size(); ++k) high_first_.emplace_back(low_first_[k].second, low_first_[k].first);
            std::sort(high_first_.begin() + static_cast<std::ptrdiff_t>(begin), high_first_.end());  // the higher stone's spheres first
            neighbours_.push_back({high, begin, low_first_.size()});
        }
    }
    first_neighbour_[stones.size()] = neighbours_.size();
}

NearSpherePairs::Range NearSpherePairs::pairs(std::size_t p, std::size_t q) const {
    const std::size_t low = std::min(p, q), high = std::max(p, q);
    for (std::size_t n = first_neighbour_[low]; n < first_neighbour_[low + 1]; ++n) {
        const Neighbour& neighbour = neighbours_[n];
        if (neighbour.stone != high) continue;
        const std::vector<SpherePair>& list = p == low ? low_first_ : high_first_;
        return {list.data() + neighbour.begin, list.data() + neighbour.end};
    }
    return {nullptr, nullptr};
}

}  // namespace rotbench
