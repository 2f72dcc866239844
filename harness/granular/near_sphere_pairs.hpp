// The sphere pairs of two stones that may touch, kept from step to step (a Verlet list with a
// skin): built for every pair of spheres of different stones closer than their radii and the
// skin, and valid while no sphere has moved more than half the skin since, because a pair that
// touches now was then closer than that. A dense packing pairs each stone with a dozen
// neighbours of 5-15 spheres each, so testing every sphere pair at every step was three
// quarters of the granular step (docs/performance.md); the list holds a few per stone pair.
#pragma once

#include "harness/granular/linked_cells.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace rotbench {

class NearSpherePairs {
public:
    using SpherePair = std::pair<std::uint32_t, std::uint32_t>;

    // Whether the list no longer holds every pair that may touch at these sphere centres.
    bool stale(const std::vector<Vec3>& centres) const;

    // Builds the list. The spheres of stone s are first_sphere[s] up to the next stone's first
    // (or the end); every one lies within reach[s] of the stone's position (sphere surface
    // included).
    void build(const std::vector<Vec3>& centres, const std::vector<double>& radii, const std::vector<Vec3>& stones,
               const std::vector<std::size_t>& first_sphere, const std::vector<double>& reach, double skin);

    // The listed sphere pairs of stones p and q, each pair as (sphere of p, sphere of q), in the
    // order of p's spheres, then q's: the order in which one would meet them testing all.
    struct Range {
        const SpherePair* begin_;
        const SpherePair* end_;
        const SpherePair* begin() const { return begin_; }
        const SpherePair* end() const { return end_; }
    };
    Range pairs(std::size_t p, std::size_t q) const;

private:
    struct Neighbour {
        std::size_t stone, begin, end;  // its pairs: [begin, end) of the two lists below
    };
    double skin_ = 0;
    std::vector<Vec3> built_at_;                      // the sphere centres of the last build
    std::vector<std::size_t> first_neighbour_;        // stone s's neighbours (higher index only):
    std::vector<Neighbour> neighbours_;               //   [first_neighbour_[s], first_neighbour_[s + 1])
    std::vector<SpherePair> low_first_, high_first_;  // the pairs as (lower stone's, higher's) and reversed
    LinkedCells cells_;
};

}  // namespace rotbench
