// The near sphere pairs hold every pair of spheres of two stones that touch, for as long as they
// say they are not stale, and only pairs that were within the skin when they were listed.
#include "harness/granular/near_sphere_pairs.hpp"
#include "harness/granular/random_stream.hpp"

#include <catch2/catch.hpp>
#include <algorithm>
#include <set>
#include <utility>

using namespace rotbench;

namespace {

// Stones of 2-6 spheres packed at random in a box, every sphere within its stone's reach.
struct Stones {
    std::vector<Vec3> centres, positions;
    std::vector<double> radii, reach;
    std::vector<std::size_t> first_sphere, owner;
};

Stones random_stones(int count, RandomStream& random) {
    Stones s;
    for (int k = 0; k < count; ++k) {
        const Vec3 x(random.uniform(0.0, 0.5), random.uniform(0.0, 0.5), random.uniform(0.0, 0.3));
        s.positions.push_back(x);
        s.first_sphere.push_back(s.centres.size());
        double reach = 0.0;
        const int spheres = 2 + k % 5;
        for (int i = 0; i < spheres; ++i) {
            const Vec3 offset(random.uniform(-0.02, 0.02), random.uniform(-0.02, 0.02), random.uniform(-0.02, 0.02));
            const double r = random.uniform(0.008, 0.02);
            s.centres.push_back(x + offset);
            s.radii.push_back(r);
            s.owner.push_back(static_cast<std::size_t>(k));
            reach = std::max(reach, offset.norm() + r);
        }
        s.reach.push_back(reach);
    }
    return s;
}

using PairSet = std::set<std::pair<std::size_t, std::size_t>>;

PairSet touching(const Stones& s) {
    PairSet out;
    for (std::size_t i = 0; i < s.centres.size(); ++i)
        for (std::size_t j = i + 1; j < s.centres.size(); ++j)
            if (s.owner[i] != s.owner[j] && (s.centres[i] - s.centres[j]).norm() < s.radii[i] + s.radii[j]) out.insert({i, j});
    return out;
}

PairSet listed(const NearSpherePairs& near, const Stones& s) {
    PairSet out;
    for (std::size_t p = 0; p < s.positions.size(); ++p)
        for (std::size_t q = 0; q < s.positions.size(); ++q) {
            if (p == q) continue;
            std::vector<std::pair<std::size_t, std::size_t>> in_order;
            for (const auto& [i, j] : near.pairs(p, q)) {
                CHECK(s.owner[i] == p);
                CHECK(s.owner[j] == q);
                in_order.emplace_back(i, j);
                out.insert(std::minmax<std::size_t>(i, j));
            }
            CHECK(std::is_sorted(in_order.begin(), in_order.end()));  // p's spheres first, as a full search meets them
            CHECK(in_order.size() == static_cast<std::size_t>(std::distance(near.pairs(q, p).begin(), near.pairs(q, p).end())));
        }
    return out;
}

}  // namespace

TEST_CASE("near sphere pairs: every touching pair is listed until a sphere moves half the skin") {
    RandomStream random(11);
    Stones stones = random_stones(400, random);
    const double skin = 0.005;
    NearSpherePairs near;
    CHECK(near.stale(stones.centres));
    near.build(stones.centres, stones.radii, stones.positions, stones.first_sphere, stones.reach, skin);
    CHECK_FALSE(near.stale(stones.centres));

    const std::vector<Vec3> built = stones.centres;
    const PairSet at_build = listed(near, stones);
    for (const auto& [i, j] : at_build)  // only pairs within the skin
        CHECK((stones.centres[i] - stones.centres[j]).norm() < stones.radii[i] + stones.radii[j] + skin * (1 + 1e-9));
    REQUIRE(touching(stones).size() > 100);  // the test sees many contacts
    CHECK(at_build.size() > touching(stones).size());

    // Every sphere moves by just under half the skin, in a random direction: the list holds.
    for (Vec3& c : stones.centres) {
        const Vec3 direction = Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1)).normalized();
        c += 0.4999 * skin * direction;
    }
    CHECK_FALSE(near.stale(stones.centres));
    const PairSet now = touching(stones);
    CHECK(std::includes(at_build.begin(), at_build.end(), now.begin(), now.end()));

    SECTION("one sphere further than half the skin, a lost number or another count makes it stale") {
        std::vector<Vec3> moved = built;
        moved[17] += Vec3(0.0, 0.5001 * skin, 0.0);
        CHECK(near.stale(moved));
        moved = built;
        moved[3].x() = NAN;
        CHECK(near.stale(moved));
        moved = built;
        moved.pop_back();
        CHECK(near.stale(moved));
    }
}
