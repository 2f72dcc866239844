// A linked-cell neighbour search: points binned into cubic cells of an edge at least the
// largest interaction distance, so that every pair closer than that lies in one cell or in two
// adjacent ones. Building is O(N) (a counting sort by cell) and so is the search for a
// bounded density, where all pairs would be O(N^2).
#pragma once

#include "schemes/bodies.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace rotbench {

class LinkedCells {
public:
    // Bins the points. `reach` is the largest distance of a pair the search must find. The
    // cells cover the points' bounding box; where they would be more than 8 per point (a
    // particle flown far away), they are made larger.
    void build(const std::vector<Vec3>& points, double reach);

    // Calls pair(i, j), i != j, once for every pair of points in the same or adjacent cells:
    // every pair closer than `reach`, and some farther ones (the caller tests the distance).
    // The order depends only on the points.
    template <class Pair>
    void for_each_pair(Pair&& pair) const {
        for (std::size_t cell = 0; cell + 1 < start_.size(); ++cell) {
            const std::size_t begin = start_[cell], end = start_[cell + 1];
            if (begin == end) continue;
            for (std::size_t a = begin; a < end; ++a)
                for (std::size_t b = a + 1; b < end; ++b) pair(order_[a], order_[b]);
            const auto [cx, cy, cz] = coordinates(cell);
            for (const auto& [dx, dy, dz] : forward_) {
                const long x = cx + dx, y = cy + dy, z = cz + dz;
                if (x < 0 || y < 0 || z < 0 || x >= dims_[0] || y >= dims_[1] || z >= dims_[2]) continue;
                const std::size_t other = index(x, y, z);
                for (std::size_t a = begin; a < end; ++a)
                    for (std::size_t b = start_[other]; b < start_[other + 1]; ++b) pair(order_[a], order_[b]);
            }
        }
    }

private:
    std::size_t index(long x, long y, long z) const { return static_cast<std::size_t>((z * dims_[1] + y) * dims_[0] + x); }
    std::array<long, 3> coordinates(std::size_t cell) const {
        const long c = static_cast<long>(cell);
        return {c % dims_[0], (c / dims_[0]) % dims_[1], c / (dims_[0] * dims_[1])};
    }

    // Half of the 26 neighbours: each adjacent pair of cells is visited once.
    static constexpr std::array<std::array<long, 3>, 13> forward_ = {{{1, 0, 0},   {-1, 1, 0}, {0, 1, 0},  {1, 1, 0},
                                                                      {-1, -1, 1}, {0, -1, 1}, {1, -1, 1}, {-1, 0, 1},
                                                                      {0, 0, 1},   {1, 0, 1},  {-1, 1, 1}, {0, 1, 1},
                                                                      {1, 1, 1}}};
    std::array<long, 3> dims_{};
    std::vector<std::size_t> start_;  // cell c holds order_[start_[c] .. start_[c + 1])
    std::vector<std::size_t> order_;  // point indices sorted by cell
};

}  // namespace rotbench
